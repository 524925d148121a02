#version 450 core
// Lit where the volume count is 0 (outside every volume), unless the receiver faces away
// from the light or lies outside the light's frustum (screen_pass.glsl's rules, the shadow
// maps' convention).
#include "testbed/glsl/receiver.glsl"

uniform sampler2D uCount;  // the signed number of volumes holding the receiver
uniform float uWeight;     // 1 for a point light, 1/N per area-light sample

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return texelFetch(uCount, pixel, 0).r == 0.0 ? uWeight : 0.0; }

#include "testbed/glsl/screen_pass.glsl"
