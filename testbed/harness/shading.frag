#version 450 core
// ShadingPass (harness/shading.h): Lambert × visibility plus ambient, the background where
// no receiver covers the pixel; shadeVisibility()'s formula, whose constants these repeat.
uniform sampler2D uPosition;       // RGBA32F, w = 1 on geometry
uniform sampler2D uShadingNormal;  // RGBA16F
uniform sampler2D uVisibility;     // R32F
uniform bool uOrthographic;
uniform vec3 uLightPosition;
uniform vec3 uLightDirection;
layout(location = 0) out vec4 color;

const float kAmbient = 0.15, kAlbedo = 0.85;
const vec3 kBackground = vec3(0.18, 0.2, 0.24);

void main() {
  const ivec2 pixel = ivec2(gl_FragCoord.xy);
  const vec4 p = texelFetch(uPosition, pixel, 0);
  if (p.w < 0.5) {
    color = vec4(kBackground, 1.0);
    return;
  }
  const vec3 n = texelFetch(uShadingNormal, pixel, 0).xyz;
  const vec3 l = uOrthographic ? -uLightDirection : normalize(uLightPosition - p.xyz);
  const float v = clamp(texelFetch(uVisibility, pixel, 0).r, 0.0, 1.0);
  color = vec4(vec3(kAlbedo * (kAmbient + (1.0 - kAmbient) * max(dot(n, l), 0.0) * v)), 1.0);
}
