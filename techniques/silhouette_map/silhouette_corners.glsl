// The four depth tests at the corners of a silhouette texel p (silhouette_map.glsl's
// coordinates: corner c ∈ {0,1}² of texel p is depth texel p − 1 + c), as component
// c.x + 2·c.y. One textureGather at uv = p / N, the corner the four depth texels share,
// returns exactly their stored depths (the border's 0 outside the map, as for
// shadowTestTexel), so this is four shadowTestTexel calls for the price of one fetch; the
// probe test in silhouette_map_glsl_test.cpp compares the two, texel by texel.
#include "testbed/glsl/shadow_test.glsl"

vec4 cornerShadowTests(ivec2 texel, float depth, float bias) {
  // textureGather's order: x (i0, j1), y (i1, j1), z (i1, j0), w (i0, j0), i0 = p − 1.
  vec4 stored = textureGather(uShadowMap, vec2(texel) / vec2(uShadowMapSize)).wzxy;
  return vec4(lessThanEqual(vec4(depth - bias), stored));  // shadowTest's comparison
}

// The straightforward form, one lookup per corner: the reference of the test.
vec4 cornerShadowTestsByTexel(ivec2 texel, float depth, float bias) {
  vec4 s;
  for (int c = 0; c < 4; ++c) s[c] = shadowTestTexel(texel - 1 + ivec2(c & 1, c >> 1), depth, bias);
  return s;
}
