#version 450 core
// The plugin fixture's copy of techniques/shadow_map/shadow_map_visibility.frag: same
// visibility as sm, from a shader the plugin embeds itself.
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"

uniform float uBias;

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return shadowTest(light.xy, light.z, uBias); }

#include "testbed/glsl/screen_pass.glsl"
