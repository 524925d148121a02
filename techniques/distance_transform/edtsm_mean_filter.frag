#version 450 core
// EDTSM's edge-aware separable mean filter (edtsm_mean_filter.glsl), one direction per draw,
// one pixel per fragment: the reference pipeline's form.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/distance_transform/edtsm_mean_filter.glsl"

uniform ivec2 uDirection;       // (1, 0) or (0, 1)
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
  int radius = filterRadius(r);
  float sum = 0.0;
  float count = 0.0;
  const int along = pixel.x * uDirection.x + pixel.y * uDirection.y;
  const ivec2 size = textureSize(uIntensity, 0);
  const int first = max(-radius, -along), last = min(radius, size.x * uDirection.x + size.y * uDirection.y - 1 - along);
  for (int i = first; i <= last; ++i) {
    vec2 tap = texelFetch(uIntensity, pixel + i * uDirection, 0).xy;
    if (!filterTakes(centre.y, tap)) continue;
    sum += tap.x;
    count += 1.0;
  }
  outIntensity = vec2(sum / count, centre.y);  // count ≥ 1: the pixel itself
}
