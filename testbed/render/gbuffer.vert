#version 450 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
uniform mat4 uViewProjection;
out vec3 vPosition;
out vec3 vNormal;
void main() {
  vPosition = inPosition;
  vNormal = inNormal;
  gl_Position = uViewProjection * vec4(inPosition, 1.0);
}
