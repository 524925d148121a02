// The banded feature transform's shared declarations (feature_transform_banded.h): its
// images' units (testbed/glsl/units.glsl) and the parabola arithmetic of phases 2 and 3.
//
// A column's sites are its rows holding a seed; site i stands for the parabola
// f_i(y) = (y - i)² + g_i², g_i the column distance to row i's nearest seed (phase 1). For
// rows a < b, f_b - f_a falls as y grows, so b beats a (strictly) from one row on and for
// good: beatsFrom(a, b). On a tie the smaller row keeps the pixel, so the transform returns
// the least (distance², row) and, within the row, phase 1's least column: the same seed as
// FeatureTransformPass. Everything is int32 and exact (sides up to kMaxExtent).

layout(local_size_x = 8, local_size_y = 8) in;

uniform ivec2 uSize;  // pixels
uniform int uBand;    // pixels a band: columns in phase 1, rows in phases 2 and 3

#include "testbed/glsl/units.glsl"

const int kNotSite = -2;  // in both links: a row without a seed, or a site out of the envelope

int floorDiv(int n, int d) { return n >= 0 ? n / d : -((d - 1 - n) / d); }  // d > 0

// The first row where site b (row b, distance gb) beats site a (row a < b, distance ga).
int beatsFrom(int a, int ga, int b, int gb) { return 1 + floorDiv((b * b - a * a) + (gb * gb - ga * ga), 2 * (b - a)); }
