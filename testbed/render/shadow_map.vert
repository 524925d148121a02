#version 450 core
layout(location = 0) in vec3 inPosition;
uniform mat4 uLightViewProjection;
void main() { gl_Position = uLightViewProjection * vec4(inPosition, 1.0); }
