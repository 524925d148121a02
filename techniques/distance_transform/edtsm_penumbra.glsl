// EDTSM's normalized distance (EDTSM* eq. 8): D is the world-space distance from the
// receiver to its nearest seed (the exact screen-space feature transform); within half the
// penumbra size P of a seed on the same surface the intensity is 1/2 - D/P on RBSM's
// shadowed side and 1/2 + D/P on its lit side; elsewhere (and for P = 0) RBSM's hard
// answer stays.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uHard;  // (RBSM visibility, camera depth or −1)
uniform float uPenumbra;

// (intensity, camera depth or −1), the layout the mean filter reads with one fetch per
// tap, at `pixel` whose nearest seed is `seed` ((-1, -1): none); (0, −1) off the receivers.
vec2 penumbraIntensity(ivec2 pixel, ivec2 seed) {
  Receiver r;
  if (!loadReceiver(pixel, r)) return vec2(0.0, -1.0);
  vec2 centre = fetchWithDepth(uHard, pixel);
  if (uPenumbra <= 0.0 || centre.y < 0.0 || seed.x < 0) return centre;
  vec2 atSeed = fetchWithDepth(uHard, seed);
  if (atSeed.y < 0.0 || !sameSurface(centre.y, atSeed.y)) return centre;
  float d = distance(r.position, texelFetch(uGPosition, seed, 0).xyz);
  if (d <= 0.5 * uPenumbra) centre.x = centre.x < 0.5 ? 0.5 - d / uPenumbra : 0.5 + d / uPenumbra;
  return centre;
}
