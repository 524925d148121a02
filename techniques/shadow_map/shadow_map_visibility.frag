#version 450 core
#define TESTBED_BIAS_MODES  // the shared set-up's bias modes (testbed/glsl/bias.glsl)
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"

uniform float uBias;

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) {
  vec3 lookup = shadowLookup(r, light);
  return shadowTest(lookup.xy, lookup.z, uBias);
}

#include "testbed/glsl/screen_pass.glsl"
