#version 450 core
// Screen pass of `rsmss`: the visibility function of rsmss.glsl, drawn by
// revectorization_screen.glsl (a classifying draw, then the edge pixels).
#include "techniques/revectorization/rsmss.glsl"

float rvScreenVisibility(vec2 uv, float z) { return rsmssVisibility(uv, z); }
bool rvScreenClassify(vec2 uv, float z, out float v) { return rsmssClassify(uv, z, v); }

#include "techniques/revectorization/revectorization_screen.glsl"
