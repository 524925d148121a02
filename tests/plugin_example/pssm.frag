#version 450 core
// Parallel-split shadow maps (Zhang et al., "Parallel-split shadow maps for large-scale
// virtual environments", VRCIA 2006), the plugin example's screen pass: each receiver is
// tested against the map of the split its camera view depth falls in, a layer of the
// cascade array, through that map's own (cropped) transform. The light's frustum rule is
// screen_pass.glsl's, on the frame's light, before this runs.
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"

const int kMaxCascades = 4;  // pssm.cpp's kMaxCascades

uniform sampler2DArray uCascades;
uniform int uCascadeCount;
// World → each map's clip space, column-major, one map after another (Program::set takes
// float arrays, so the matrices travel as their 16 floats each).
uniform float uCascadeMatrices[kMaxCascades * 16];
uniform float uSplitFar[kMaxCascades];  // the far view depth of each split
uniform vec3 uCameraEye;
uniform vec3 uCameraForward;  // unit
uniform float uBias;

mat4 cascadeViewProjection(int cascade) {
  mat4 m;
  for (int column = 0; column < 4; ++column)
    for (int row = 0; row < 4; ++row) m[column][row] = uCascadeMatrices[cascade * 16 + column * 4 + row];
  return m;
}

// The split of a receiver at camera view depth `depth`: the first whose far end lies beyond.
int cascadeOf(float depth) {
  for (int i = 0; i < uCascadeCount - 1; ++i)
    if (depth <= uSplitFar[i]) return i;
  return uCascadeCount - 1;
}

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) {
  int cascade = cascadeOf(dot(r.position - uCameraEye, uCameraForward));
  vec3 map = lightSpace(cascadeViewProjection(cascade), r.position);
  return shadowTest(uCascades, cascade, map.xy, map.z, uBias);
}

#include "testbed/glsl/screen_pass.glsl"
