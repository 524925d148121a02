#version 450 core
// Feature transform, pass 1 (feature_transform_row_sweep.glsl) over a seed mask: a seed
// where the red channel > 0.5.
uniform sampler2D uSeeds;

const int kRowSpan = 1 << 30;  // no per-span work
void featureTransformRowBegin(int y) {}
bool featureTransformIsSeed(ivec2 pixel) { return texelFetch(uSeeds, pixel, 0).r > 0.5; }
void featureTransformSpanEnd(ivec2 pixel) {}

#include "techniques/distance_transform/feature_transform_row_sweep.glsl"

void main() { featureTransformRow(); }
