#version 450 core
// The scene from the light (the shared shadow map's transform) with its linear depth.
#include "techniques/prefiltered/light_depth.glsl"
layout(location = 0) in vec3 inPosition;
layout(location = 0) out float vLightDepth;
void main() {
  vLightDepth = lightLinearDepth(inPosition);
  gl_Position = uLightViewProjection * vec4(inPosition, 1.0);
}
