#version 450 core
// RPCF's tile bounds (rpcf_tiles.h): for the tile of shadow-map column x and rows 2y,
// 2y + 1, the least stored depth over the columns x − h − 1 … x + h + 1 (the block's and
// its rim's, h = RPCF_APRON = k/2) and the greatest over the same columns
// (RPCF_BOTH_SIDES) or over the taps' columns x − h … x + h only, from (k + 3)/2 gathers
// along the row pair (rvGatherCross says why a gather reads the stored values). Texels
// beyond the map read the border depth 0, as every lookup of the family gets it.
#include "testbed/glsl/shadow_test.glsl"

layout(location = 0) out vec2 outBounds;  // (least, greatest)

void main() {
  ivec2 tile = ivec2(gl_FragCoord.xy);
  int left = tile.x - RPCF_APRON - 1;  // the rim's column; the block's last is left + k + 1
  vec2 texel = 1.0 / vec2(uShadowMapSize);
  vec2 bounds = vec2(2.0, -1.0);  // depths lie in [0, 1]
  for (int j = 0; j <= RPCF_APRON + 1; ++j) {
    // Columns left + 2j and left + 2j + 1 of both rows, around their shared corner; gather
    // order (i0,j1), (i1,j1), (i1,j0), (i0,j0).
    vec4 g = textureGather(uShadowMap, vec2(left + 2 * j + 1, 2 * tile.y + 1) * texel);
    for (int c = 0; c < 2; ++c) {
      int column = 2 * j + c;  // from the rim's, 0 … k + 1 (k + 2 lies beyond)
      vec2 both = c == 0 ? g.wx : g.zy;
      if (column > 2 * RPCF_APRON + 2) continue;
      bounds.x = min(bounds.x, min(both.x, both.y));
#ifndef RPCF_BOTH_SIDES
      if (column == 0 || column == 2 * RPCF_APRON + 2) continue;  // the rim: taps only
#endif
      bounds.y = max(bounds.y, max(both.x, both.y));
    }
  }
  outBounds = bounds;
}
