#version 450 core
// Screen pass of `rpcf-rsmss`: the visibility function of rpcf_rsmss.glsl, drawn by
// testbed/glsl/screen_pass.glsl (a classifying draw, then the edge pixels).
#include "testbed/glsl/receiver.glsl"
#include "techniques/revectorization/rpcf_rsmss.glsl"

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return rpcfRsmssEdgeVisibility(light.xy, light.z); }
bool screenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  return rpcfTileClassify(light.xy, light.z, v);
}

#include "testbed/glsl/screen_pass.glsl"
