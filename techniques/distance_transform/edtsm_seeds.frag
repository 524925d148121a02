#version 450 core
// EDTSM seeds (EDTSM* §3.3): a receiver is a seed when one of its 8 neighbours on the
// same surface has the other hard visibility (RBSM's result, 0 or 1). Pixels with depth −1
// (off the receivers, facing away from the light) take no part.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uHard;  // (RBSM visibility, camera depth or −1)
layout(location = 0) out float outSeed;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec2 centre = fetchWithDepth(uHard, pixel);
  outSeed = 0.0;
  if (centre.y < 0.0) return;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      vec2 neighbour = fetchWithDepth(uHard, pixel + ivec2(dx, dy));
      if (neighbour.y < 0.0 || !sameSurface(centre.y, neighbour.y)) continue;
      if (neighbour.x != centre.x) outSeed = 1.0;
    }
}
