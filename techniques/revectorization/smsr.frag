#version 450 core
// Screen pass of `smsr`: the visibility function of smsr.glsl, drawn by
// testbed/glsl/screen_pass.glsl (a classifying draw, then the edge pixels).
#include "testbed/glsl/receiver.glsl"
#include "testbed/render/revectorization/smsr.glsl"

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return smsrVisibility(light.xy, light.z); }
bool screenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  return smsrClassify(light.xy, light.z, v);
}

#include "testbed/glsl/screen_pass.glsl"
