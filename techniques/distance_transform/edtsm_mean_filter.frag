#version 450 core
// EDTSM's edge-aware separable mean filter (EDTSM* §3.4), one direction per draw. The
// window is the user's world-space width seen at the receiver's distance (eqs. 9–10:
// w_screen = w · z_screen / z_eye with z_screen = 1 / (2 tan(fov_y / 2)), a fraction of the
// screen height), so the blur keeps its world size as the camera moves; only neighbours on
// the same surface and facing the light take part.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uIntensity;   // (intensity, camera depth or −1)
uniform ivec2 uDirection;       // (1, 0) or (0, 1)
uniform float uFilterWidth;     // world units
uniform float uScreenDistance;  // z_screen
uniform vec3 uCameraPosition;
uniform int uMaxRadius;         // pixels
layout(location = 0) out vec2 outIntensity;  // the same layout, for the second direction

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  Receiver r;
  if (!loadReceiver(pixel, r)) discard;
  vec2 centre = texelFetch(uIntensity, pixel, 0).xy;
  if (centre.y < 0.0) {  // shadowed by the facing rule, as in every technique
    outIntensity = vec2(0.0, -1.0);
    return;
  }
  float heightPx = float(textureSize(uGPosition, 0).y);
  float widthPx = uFilterWidth * uScreenDistance / distance(r.position, uCameraPosition) * heightPx;
  int radius = min(int(floor(0.5 * widthPx)), uMaxRadius);
  float sum = 0.0;
  float count = 0.0;
  // Taps off the screen count as depth −1 (fetchWithDepth): the loop leaves them out.
  const int along = pixel.x * uDirection.x + pixel.y * uDirection.y;
  const ivec2 size = textureSize(uIntensity, 0);
  const int first = max(-radius, -along), last = min(radius, size.x * uDirection.x + size.y * uDirection.y - 1 - along);
  for (int i = first; i <= last; ++i) {
    vec2 tap = texelFetch(uIntensity, pixel + i * uDirection, 0).xy;
    if (tap.y < 0.0 || !sameSurface(centre.y, tap.y)) continue;  // −1: off the receivers or facing away
    sum += tap.x;
    count += 1.0;
  }
  outIntensity = vec2(sum / count, centre.y);  // count ≥ 1: the pixel itself
}
