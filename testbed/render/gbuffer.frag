#version 450 core
layout(location = 0) in vec3 vPosition;
layout(location = 1) in vec3 vNormal;
layout(location = 2) flat in vec3 vFaceNormal;
layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;
layout(location = 2) out vec4 outShadingNormal;
void main() {
  // Two-sided: the back of an open surface is lit or shadowed as seen from its side.
  float side = gl_FrontFacing ? 1.0 : -1.0;
  outPosition = vec4(vPosition, 1.0);
  outNormal = vec4(side * normalize(vFaceNormal), 0.0);
  outShadingNormal = vec4(side * normalize(vNormal), 0.0);
}
