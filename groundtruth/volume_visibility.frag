#version 450 core
// Drawn where the stencil count is 0 (outside every volume): lit, unless the receiver
// faces away from the light or lies outside the light's frustum (screen_pass.glsl's rules,
// the shadow maps' convention).
#include "testbed/glsl/receiver.glsl"

uniform float uWeight;  // 1 for a point light, 1/N per area-light sample

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return uWeight; }

#include "testbed/glsl/screen_pass.glsl"
