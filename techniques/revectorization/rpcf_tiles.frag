#version 450 core
// RPCF's tile bounds (rpcf_tiles.h): the least and greatest stored depth over each 2×2
// block of shadow-map texels with an apron of RPCF_APRON texels around it (the texels
// 2·tile − a … 2·tile + 1 + a a side), from (a + 1)² gathers (rvGatherCross says why a
// gather reads the stored values). Texels beyond the map read the border depth 0, as every
// lookup of the family gets it.
#include "testbed/glsl/shadow_test.glsl"

layout(location = 0) out vec2 outBounds;  // (least, greatest)

void main() {
  ivec2 first = ivec2(gl_FragCoord.xy) * 2 - RPCF_APRON;
  vec2 texel = 1.0 / vec2(uShadowMapSize);
  vec2 bounds = vec2(2.0, -1.0);  // depths lie in [0, 1]
  for (int y = 1; y <= 2 * RPCF_APRON + 1; y += 2)
    for (int x = 1; x <= 2 * RPCF_APRON + 1; x += 2) {
      // The 2×2 texels around the corner (first + (x, y)).
      vec4 g = textureGather(uShadowMap, vec2(first + ivec2(x, y)) * texel);
      bounds = vec2(min(bounds.x, min(min(g.x, g.y), min(g.z, g.w))), max(bounds.y, max(max(g.x, g.y), max(g.z, g.w))));
    }
  outBounds = bounds;
}
