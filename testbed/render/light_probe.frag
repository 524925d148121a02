#version 450 core
// Test harness only (light_glsl_test.cpp): evaluates PROBE(a, b), a #define given by the
// test, on texel i of two 1×N inputs, so the tests check light.glsl's own code.
#include "testbed/glsl/light.glsl"
uniform sampler2D uA;
uniform sampler2D uB;
layout(location = 0) out vec4 outResult;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  outResult = vec4(PROBE(texelFetch(uA, texel, 0), texelFetch(uB, texel, 0)));
}
