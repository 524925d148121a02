#version 450 core
// Screen pass of `rpcf-smsr`: the visibility function of rpcf_smsr.glsl, drawn by
// revectorization_screen.glsl (a classifying draw, then the edge pixels).
#include "techniques/revectorization/rpcf_smsr.glsl"

float rvScreenVisibility(vec2 uv, float z) { return rpcfSmsrEdgeVisibility(uv, z); }
bool rvScreenClassify(vec2 uv, float z, out float v) { return rpcfSmsrClassify(uv, z, v); }

#include "techniques/revectorization/revectorization_screen.glsl"
