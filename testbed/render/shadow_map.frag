#version 450 core
// Depth only: the fixed-function depth (with polygon offset) is the shadow map. With a 32f
// depth buffer, whose polygon-offset unit varies with depth, the constant term is added
// here instead, in 16-bit steps (render/shadow_map_pass.cpp); the slope term stays in the
// fixed function, whose offset gl_FragCoord.z already holds.
#ifdef CONSTANT_OFFSET_IN_SHADER
uniform float uConstantOffset;
void main() { gl_FragDepth = gl_FragCoord.z + uConstantOffset; }
#else
void main() {}
#endif
