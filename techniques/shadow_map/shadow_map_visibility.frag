#version 450 core
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"

uniform float uBias;

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return shadowTest(light.xy, light.z, uBias); }

#include "testbed/glsl/screen_pass.glsl"
