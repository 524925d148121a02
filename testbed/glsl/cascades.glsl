// The cascades of the run's shadow-map set-up (technique/shadow_setup.h, docs/cascades.md),
// compiled in where TESTBED_CASCADES is defined (the cascade program of
// render/shadow_map_screen_technique.h): each cascade's map is a layer of uShadowMaps, and
// a receiver reads the map of the split its view depth, along the camera the maps were
// fitted to, falls in. screen_pass.glsl sets gCascade before screenVisibility runs, so the
// tests without a map (shadow_test.glsl, kernel.glsl) read the receiver's cascade.
#include "testbed/glsl/light.glsl"

const int kMaxCascades = 4;  // technique/shadow_setup.h's kMaxCascades

uniform sampler2DArray uShadowMaps;
uniform int uCascadeCount;
// World → each map's clip space, column-major, one map after another (Program::set takes
// float arrays, so each matrix travels as its 16 floats).
uniform float uCascadeMatrices[kMaxCascades * 16];
uniform float uCascadeSplitFar[kMaxCascades];  // the far view depth of each split
uniform float uCascadeSplitNear[kMaxCascades];  // and its near view depth
uniform float uCascadeBlendBand;  // --blend-band: F, a fraction of a slice's depth; 0 off
// Each map's projection terms that scale its texels (light.glsl texelWorldSize): P₀₀, P₁₁,
// P₂₃ and P₃₃ (column-major [column][row]), one map after another.
uniform float uCascadeProjectionScale[kMaxCascades * 4];
uniform vec3 uCascadeEye;      // the camera the maps were fitted to
uniform vec3 uCascadeForward;  // its unit view direction

int gCascade = 0;  // the receiver's cascade (screen_pass.glsl)

mat4 cascadeViewProjection(int cascade) {
  mat4 m;
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) m[column][row] = uCascadeMatrices[cascade * 16 + column * 4 + row];
  return m;
}

// The split of a receiver at world position `world`: the first whose far end lies at or
// beyond its view depth; nearer than the first split, the first; beyond the last, the last.
int cascadeOf(vec3 world) {
  float depth = dot(world - uCascadeEye, uCascadeForward);
  for (int i = 0; i < uCascadeCount - 1; ++i)
    if (depth <= uCascadeSplitFar[i]) return i;
  return uCascadeCount - 1;
}

// World size of one texel of a cascade's map of `mapSize` texels at light view depth
// `viewDepth` (light.glsl texelWorldSize, from the terms that carry it).
vec2 cascadeTexelWorld(int cascade, ivec2 mapSize, float viewDepth) {
  mat4 p = mat4(0.0);
  p[0][0] = uCascadeProjectionScale[cascade * 4];
  p[1][1] = uCascadeProjectionScale[cascade * 4 + 1];
  p[2][3] = uCascadeProjectionScale[cascade * 4 + 2];
  p[3][3] = uCascadeProjectionScale[cascade * 4 + 3];
  return texelWorldSize(p, mapSize, viewDepth);
}

// The weight of the next cascade's lookup for a receiver at `world` in `cascade`
// (--blend-band F, ShadowSetup::blendBand): 0 before the last fraction F of the slice's
// depth, then rising linearly to 1 at its far split, where the next cascade takes over
// alone; 0 in the last cascade, which has no next.
float cascadeBlendWeight(vec3 world, int cascade) {
  if (uCascadeBlendBand <= 0.0 || cascade >= uCascadeCount - 1) return 0.0;
  float depth = dot(world - uCascadeEye, uCascadeForward);
  float farEnd = uCascadeSplitFar[cascade];
  float start = farEnd - uCascadeBlendBand * (farEnd - uCascadeSplitNear[cascade]);
  return depth > start ? clamp((depth - start) / (farEnd - start), 0.0, 1.0) : 0.0;
}
