#version 450 core
// Screen pass of `smsr`: the visibility function of smsr.glsl, drawn by
// revectorization_screen.glsl (a classifying draw, then the edge pixels).
#include "testbed/glsl/receiver.glsl"
#include "techniques/revectorization/smsr.glsl"

float rvScreenVisibility(ivec2 pixel, Receiver r, vec3 light) { return smsrVisibility(light.xy, light.z); }
bool rvScreenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  return smsrClassify(light.xy, light.z, v);
}

#include "techniques/revectorization/revectorization_screen.glsl"
