#version 450 core
in vec3 vPosition;
in vec3 vNormal;
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
void main() {
  // Two-sided: the back of an open surface is lit or shadowed as seen from its side.
  vec3 n = normalize(vNormal);
  outPosition = vec4(vPosition, 1.0);
  outNormal = vec4(gl_FrontFacing ? n : -n, 0.0);
}
