#version 450 core
// Feature transform, pass 1 (feature_transform_row_sweep.glsl) over a seed mask: a seed
// where the red channel > 0.5.
uniform sampler2D uSeeds;

bool featureTransformIsSeed(ivec2 pixel) { return texelFetch(uSeeds, pixel, 0).r > 0.5; }

#include "techniques/distance_transform/feature_transform_row_sweep.glsl"

void main() { featureTransformRow(); }
