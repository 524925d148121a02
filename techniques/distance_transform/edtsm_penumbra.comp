#version 450 core
// EDTSM's penumbra (edtsm_penumbra.glsl) evaluated by the feature transform's column pass
// the moment it finds each pixel's nearest seed, so the seed never goes through an image
// and the penumbra needs no draw of its own. On the way it ORs, per tile, the kinds of
// intensity the receivers hold, for the mean filter's tiles (edtsm_filter_tiles.h).
#include "techniques/distance_transform/edtsm_penumbra.glsl"

layout(rg32f, binding = 0) uniform writeonly image2D uIntensity;
layout(r32ui, binding = 1) uniform uimage2D uTileKinds;  // cleared to 0 before

const int kTile = 32;  // FilterTiles::kTile

uint gKinds = 0u;  // this column's kinds in the current tile

void featureTransformStore(ivec2 pixel, ivec2 seed) {
  const vec2 v = penumbraIntensity(pixel, seed);
  imageStore(uIntensity, pixel, vec4(v, 0.0, 0.0));
  // Depth −1 takes no part, as in the filter; +0 and 1 exactly, or anything else.
  if (!(v.y < 0.0)) gKinds |= floatBitsToUint(v.x) == 0u ? 1u : v.x == 1.0 ? 2u : 4u;
  // The rows come last to first, so a tile's first row is the last this column visits.
  if (pixel.y % kTile == 0) {
    if (gKinds != 0u) imageAtomicOr(uTileKinds, pixel / kTile, gKinds);
    gKinds = 0u;
  }
}

#include "techniques/distance_transform/feature_transform_envelope.glsl"

void main() { featureTransformColumn(); }
