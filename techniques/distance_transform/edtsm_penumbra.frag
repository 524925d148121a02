#version 450 core
// EDTSM's normalized distance (seed 004 eq. 8): D is the world-space distance from the
// receiver to its nearest seed (the exact screen-space feature transform); within half the
// penumbra size P of a seed on the same surface the intensity is 1/2 - D/P on RBSM's
// shadowed side and 1/2 + D/P on its lit side; elsewhere (and for P = 0) RBSM's hard
// answer stays.
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uHardVisibility;
uniform isampler2D uNearestSeed;  // pixel coordinates of the nearest seed, (-1, -1): none
uniform float uPenumbra;
// x: the intensity; y: the camera depth, or −1 where the mean filter must not look (receivers
// facing away from the light), so the filter needs one fetch per tap.
layout(location = 0) out vec2 outIntensity;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 position;
  float depth;
  if (!receiverDepth(pixel, position, depth)) discard;
  float v = texelFetch(uHardVisibility, pixel, 0).r;
  outIntensity = vec2(v, litByFacing(pixel) ? depth : -1.0);
  ivec2 seed = texelFetch(uNearestSeed, pixel, 0).xy;
  vec3 seedPosition;
  float seedDepth;
  if (uPenumbra <= 0.0 || outIntensity.y < 0.0 || seed.x < 0 || !receiverDepth(seed, seedPosition, seedDepth) || !sameSurface(depth, seedDepth)) return;
  float d = distance(position, seedPosition);
  if (d <= 0.5 * uPenumbra) outIntensity.x = v < 0.5 ? 0.5 - d / uPenumbra : 0.5 + d / uPenumbra;
}
