#version 450 core
// EDTSM's seeds (edtsm_seeds.glsl) as a mask of their own: the `reference` pipeline's.
#include "techniques/distance_transform/edtsm_seeds.glsl"

layout(location = 0) out float outSeed;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec2 centre = fetchWithDepth(uHard, pixel);
  outSeed = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (seedNeighbour(centre, fetchWithDepth(uHard, pixel + ivec2(dx, dy)))) outSeed = 1.0;
}
