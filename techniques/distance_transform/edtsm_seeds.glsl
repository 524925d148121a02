// EDTSM seeds (EDTSM* §3.3): a receiver is a seed when one of its 8 neighbours on the
// same surface has the other hard visibility (RBSM's result, 0 or 1). Pixels with depth −1
// (off the receivers, facing away from the light) take no part.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uHard;  // (RBSM visibility, camera depth or −1)

// Whether `neighbour` ((visibility, depth) of edtsm_screen.glsl) makes `centre` a seed.
bool seedNeighbour(vec2 centre, vec2 neighbour) {
  return !(centre.y < 0.0) && !(neighbour.y < 0.0) && sameSurface(centre.y, neighbour.y) && neighbour.x != centre.x;
}
