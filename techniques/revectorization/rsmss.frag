#version 450 core
// Screen pass of `rsmss`: the visibility function of rsmss.glsl, drawn by
// revectorization_screen.glsl (a classifying draw, then the edge pixels).
#include "testbed/glsl/receiver.glsl"
#include "techniques/revectorization/rsmss.glsl"

float rvScreenVisibility(ivec2 pixel, Receiver r, vec3 light) { return rsmssVisibility(light.xy, light.z); }
bool rvScreenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  return rsmssClassify(light.xy, light.z, v);
}

#include "techniques/revectorization/revectorization_screen.glsl"
