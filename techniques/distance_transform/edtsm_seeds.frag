#version 450 core
// EDTSM seeds (seed 004 §3.3): a receiver is a seed when one of its 8 neighbours on the
// same surface has the other hard visibility (RBSM's result, 0 or 1); receivers facing
// away from the light take no part.
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uHardVisibility;
layout(location = 0) out float outSeed;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 position;
  float depth;
  outSeed = 0.0;
  if (!receiverDepth(pixel, position, depth) || !litByFacing(pixel)) return;
  float v = texelFetch(uHardVisibility, pixel, 0).r;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      ivec2 q = pixel + ivec2(dx, dy);
      vec3 qPosition;
      float qDepth;
      if ((dx == 0 && dy == 0) || !receiverDepth(q, qPosition, qDepth) || !sameSurface(depth, qDepth) ||
          !litByFacing(q))
        continue;
      if (texelFetch(uHardVisibility, q, 0).r != v) outSeed = 1.0;
    }
}
