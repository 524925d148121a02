#version 450 core
// EDTSM's normalized distance (EDTSM* eq. 8): D is the world-space distance from the
// receiver to its nearest seed (the exact screen-space feature transform); within half the
// penumbra size P of a seed on the same surface the intensity is 1/2 - D/P on RBSM's
// shadowed side and 1/2 + D/P on its lit side; elsewhere (and for P = 0) RBSM's hard
// answer stays.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uHard;          // (RBSM visibility, camera depth or −1)
uniform isampler2D uNearestSeed;  // pixel coordinates of the nearest seed, (-1, -1): none
uniform float uPenumbra;
// (intensity, camera depth or −1): the mean filter then needs one fetch per tap.
layout(location = 0) out vec2 outIntensity;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  Receiver r;
  if (!loadReceiver(pixel, r)) discard;
  vec2 centre = fetchWithDepth(uHard, pixel);
  outIntensity = centre;
  ivec2 seed = texelFetch(uNearestSeed, pixel, 0).xy;
  if (uPenumbra <= 0.0 || centre.y < 0.0 || seed.x < 0) return;
  vec2 atSeed = fetchWithDepth(uHard, seed);
  if (atSeed.y < 0.0 || !sameSurface(centre.y, atSeed.y)) return;
  float d = distance(r.position, texelFetch(uGPosition, seed, 0).xyz);
  if (d <= 0.5 * uPenumbra) outIntensity.x = centre.x < 0.5 ? 0.5 - d / uPenumbra : 0.5 + d / uPenumbra;
}
