#version 450 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec3 inFaceNormal;
uniform mat4 uViewProjection;
layout(location = 0) out vec3 vPosition;
layout(location = 1) out vec3 vNormal;
layout(location = 2) flat out vec3 vFaceNormal;
void main() {
  vPosition = inPosition;
  vNormal = inNormal;
  vFaceNormal = inFaceNormal;
  gl_Position = uViewProjection * vec4(inPosition, 1.0);
}
