#version 450 core
// Volume triangles, some corners at infinity (w = 0); depth clamp keeps them unclipped.
layout(location = 0) in vec4 inPosition;
layout(location = 1) in vec4 inPlane;
layout(location = 2) in float inLightCap;
layout(location = 3) in float inWeight;
uniform mat4 uViewProjection;
layout(location = 0) flat out vec4 vPlane;
layout(location = 1) flat out float vLightCap;
layout(location = 2) flat out float vWeight;
void main() {
  vPlane = inPlane;
  vLightCap = inLightCap;
  vWeight = inWeight;
  gl_Position = uViewProjection * inPosition;
}
