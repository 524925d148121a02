// The binary shadow test s ∈ {0 shadow, 1 lit} against the nearest-filtered shadow map.
// Outside the map the border depth 0 answers, so everything outside reads as shadow.
uniform sampler2D uShadowMap;
uniform ivec2 uShadowMapSize;

float shadowTest(vec2 uv, float depth, float bias) {
  float stored = texture(uShadowMap, uv).r;
  return depth - bias <= stored ? 1.0 : 0.0;
}

// The same at an explicit texel (neighbour tests of the revectorization family).
float shadowTestTexel(ivec2 texel, float depth, float bias) {
  return shadowTest((vec2(texel) + 0.5) / vec2(uShadowMapSize), depth, bias);
}
