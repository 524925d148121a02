#version 450 core
// EDTSM's penumbra pass (edtsm_penumbra.glsl) over the nearest-seed image, as its own
// full-screen draw: the `reference` pipeline's.
#include "techniques/distance_transform/edtsm_penumbra.glsl"

uniform isampler2D uNearestSeed;  // pixel coordinates of the nearest seed, (-1, -1): none
layout(location = 0) out vec2 outIntensity;

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);
  outIntensity = penumbraIntensity(pixel, texelFetch(uNearestSeed, pixel, 0).xy);
}
