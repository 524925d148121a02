#version 450 core
// Test harness only (light_glsl_test.cpp): evaluates PROBE(a, b), a #define given by the
// test, on texel i of two 1×N inputs, so the tests check light.glsl's own code (and
// bias.glsl's, where the test defines TESTBED_BIAS_MODES).
#include "testbed/glsl/light.glsl"
#ifdef TESTBED_BIAS_MODES  // the bias modes' helpers too (glsl/bias.glsl)
#include "testbed/glsl/shadow_test.glsl"
// The tap (uv, depth) as biasedTap() returns it, for the receiver at `position` with
// `normal` looked up through shadowLookup().
vec4 probeBiasedTap(vec3 position, vec3 normal, vec2 uv, float depth) {
  shadowLookup(Receiver(position, normal), lightCoordinates(position));
  biasedTap(uv, depth);
  return vec4(uv, depth, 0.0);
}
#endif
uniform sampler2D uA;
uniform sampler2D uB;
layout(location = 0) out vec4 outResult;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  outResult = vec4(PROBE(texelFetch(uA, texel, 0), texelFetch(uB, texel, 0)));
}
