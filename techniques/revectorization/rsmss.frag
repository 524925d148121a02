#version 450 core
// Screen pass of `rsmss`: the visibility function of rsmss.glsl, drawn by
// testbed/glsl/screen_pass.glsl (a classifying draw, then the edge pixels).
#include "testbed/glsl/receiver.glsl"
#include "techniques/revectorization/rsmss.glsl"

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return rsmssVisibility(light.xy, light.z); }
bool screenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  return rsmssClassify(light.xy, light.z, v);
}

#include "testbed/glsl/screen_pass.glsl"
