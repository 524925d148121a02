#version 450 core
// Feature transform, pass 2 (feature_transform_envelope.glsl) into the nearest-seed image.
#include "testbed/glsl/units.glsl"
layout(rg32i, binding = kEdtsmOutputImageUnit) uniform writeonly iimage2D uNearest;

const int kColumnSpan = 1 << 30;  // no per-span work
void featureTransformStore(ivec2 pixel, ivec2 seed) { imageStore(uNearest, pixel, ivec4(seed, 0, 0)); }
void featureTransformSpanEnd(ivec2 pixel) {}

#include "techniques/distance_transform/feature_transform_envelope.glsl"

void main() { featureTransformColumn(); }
