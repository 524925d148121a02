#version 450 core
// EDTSM's edge-aware separable mean filter (seed 004 §3.4), one direction per draw. The
// window is the user's world-space width seen at the receiver's distance (eqs. 9–10:
// w_screen = w · z_screen / z_eye with z_screen = 1 / (2 tan(fov_y / 2)), a fraction of the
// screen height), so the blur keeps its world size as the camera moves; only neighbours on
// the same surface and facing the light take part.
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uIntensity;
uniform ivec2 uDirection;     // (1, 0) or (0, 1)
uniform float uFilterWidth;   // world units
uniform float uScreenDistance;  // z_screen
uniform vec3 uCameraPosition;
uniform int uMaxRadius;       // pixels
layout(location = 0) out float outIntensity;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 position;
  float depth;
  if (!receiverDepth(pixel, position, depth)) discard;
  if (!litByFacing(pixel)) {  // shadowed by the facing rule, as in every technique
    outIntensity = 0.0;
    return;
  }
  float heightPx = float(textureSize(uGPosition, 0).y);
  float widthPx = uFilterWidth * uScreenDistance / distance(position, uCameraPosition) * heightPx;
  int radius = min(int(floor(0.5 * widthPx)), uMaxRadius);
  float sum = 0.0;
  float count = 0.0;
  for (int i = -radius; i <= radius; ++i) {
    ivec2 q = pixel + i * uDirection;
    vec3 qPosition;
    float qDepth;
    if (!receiverDepth(q, qPosition, qDepth) || !sameSurface(depth, qDepth) || !litByFacing(q)) continue;
    sum += texelFetch(uIntensity, q, 0).r;
    count += 1.0;
  }
  outIntensity = sum / count;  // count ≥ 1: the pixel itself
}
