#version 450 core
// Depth only: the fixed-function depth (with polygon offset) is the shadow map.
void main() {}
