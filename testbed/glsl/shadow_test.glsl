// The binary shadow test s ∈ {0 shadow, 1 lit} against a nearest-filtered depth map.
// Outside the map the border depth 0 answers, so everything outside reads as shadow.
// Each test takes the map it reads (a 2D map, or a layer of an array of maps: cascades);
// the forms without one read the shared shadow map, uShadowMap (bindShadowMap,
// render/shadow_map_pass.h), or with TESTBED_CASCADES the receiver's cascade's layer of
// uShadowMaps (glsl/cascades.glsl).
#ifdef TESTBED_CASCADES
#include "testbed/glsl/cascades.glsl"
#else
uniform sampler2D uShadowMap;
#endif
uniform ivec2 uShadowMapSize;  // a map's size (each cascade's)
// The set-up's bias modes, for a shader that takes them (shadowLookup, biasedTap).
#ifdef TESTBED_BIAS_MODES
#include "testbed/glsl/bias.glsl"
#endif

// The comparison itself, the one every test below makes.
float shadowCompare(float stored, float depth, float bias) { return depth - bias <= stored ? 1.0 : 0.0; }

float shadowTest(sampler2D map, vec2 uv, float depth, float bias) {
  return shadowCompare(texture(map, uv).r, depth, bias);
}
float shadowTest(sampler2DArray maps, int layer, vec2 uv, float depth, float bias) {
  return shadowCompare(texture(maps, vec3(uv, float(layer))).r, depth, bias);
}
// With TESTBED_BIAS_MODES, this form takes the tap as the run's bias mode compares it.
float shadowTest(vec2 uv, float depth, float bias) {
#ifdef TESTBED_BIAS_MODES
  biasedTap(uv, depth);
#endif
#ifdef TESTBED_CASCADES
  return shadowTest(uShadowMaps, gCascade, uv, depth, bias);
#else
  return shadowTest(uShadowMap, uv, depth, bias);
#endif
}

// The same at an explicit texel of a map of `size` texels (neighbour tests of the
// revectorization family): the nearest lookup at the texel's centre.
vec2 shadowTexelUv(ivec2 texel, ivec2 size) { return (vec2(texel) + 0.5) / vec2(size); }
float shadowTestTexel(sampler2D map, ivec2 texel, float depth, float bias) {
  return shadowTest(map, shadowTexelUv(texel, textureSize(map, 0)), depth, bias);
}
float shadowTestTexel(sampler2DArray maps, int layer, ivec2 texel, float depth, float bias) {
  return shadowTest(maps, layer, shadowTexelUv(texel, textureSize(maps, 0).xy), depth, bias);
}
float shadowTestTexel(ivec2 texel, float depth, float bias) {
  return shadowTest(shadowTexelUv(texel, uShadowMapSize), depth, bias);
}
