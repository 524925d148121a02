#version 450 core
// The paper path's resolve: the stencil test (equal to 0: outside every volume) lets only
// lit receivers through, which then add the light's weight unless they face away from the
// light or lie outside its frustum (screen_pass.glsl's rules, the shadow maps' convention).
#include "testbed/glsl/receiver.glsl"

uniform float uWeight;  // 1 for a point light, 1/N per area-light sample

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return uWeight; }

#include "testbed/glsl/screen_pass.glsl"
