#version 450 core
// Screen pass of `rpcf-rsmss`: the visibility function of rpcf_rsmss.glsl, drawn by
// revectorization_screen.glsl (a classifying draw, then the edge pixels).
#include "techniques/revectorization/rpcf_rsmss.glsl"

float rvScreenVisibility(vec2 uv, float z) { return rpcfRsmssEdgeVisibility(uv, z); }
bool rvScreenClassify(vec2 uv, float z, out float v) { return rpcfRsmssClassify(uv, z, v); }

#include "techniques/revectorization/revectorization_screen.glsl"
