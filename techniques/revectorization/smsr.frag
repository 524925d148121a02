#version 450 core
// Screen pass of `smsr`: the visibility function of smsr.glsl, drawn by
// revectorization_screen.glsl (a classifying draw, then the edge pixels).
#include "techniques/revectorization/smsr.glsl"

float rvScreenVisibility(vec2 uv, float z) { return smsrVisibility(uv, z); }
bool rvScreenClassify(vec2 uv, float z, out float v) { return smsrClassify(uv, z, v); }

#include "techniques/revectorization/revectorization_screen.glsl"
