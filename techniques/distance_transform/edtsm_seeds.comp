#version 450 core
// EDTSM's seeds (edtsm_seeds.glsl) found by the feature transform's row pass itself
// (feature_transform_row_sweep.glsl), so they need neither a draw nor a mask: a 3×3
// window of the hard visibility slides along the row, three fetches a pixel. On the way
// it records, per tile, what edtsm_penumbra_band.h needs (whether the tile holds a seed,
// its least receiver depth) and the mean filter's kinds of the hard visibility
// (edtsm_filter_tiles.h), one atomic each per row of a tile.
#include "testbed/glsl/units.glsl"
#include "techniques/distance_transform/edtsm_seeds.glsl"
#include "techniques/distance_transform/edtsm_tiles.glsl"

layout(r32ui, binding = kTileKindsImageUnit) uniform uimage2D uTileKinds;     // cleared to 0 before
layout(r32ui, binding = kTileSeedsImageUnit) uniform uimage2D uTileSeeds;     // cleared to 0 before
layout(r32ui, binding = kTileMinDepthImageUnit) uniform uimage2D uTileMinDepth;  // cleared to ~0 before
// uHard again, as an image: on llvmpipe an imageLoad costs fewer instructions than a
// texelFetch of the same texel, and this pass makes three a pixel.
layout(rg32f, binding = kEdtsmInputImageUnit) uniform readonly image2D uHardImage;

// Columns x - 1, x and x + 1 of the window, each rows y - 1, y and y + 1.
vec2 gBefore[3], gAt[3], gAfter[3];
ivec2 gSize;         // the screen's
bool gRowInside[3];  // whether rows y - 1, y and y + 1 lie on it
// This row's record of the current span, one tile wide (kTile = kBandTile);
// the depth as bits (non-negative floats order as their bits do).
uint gTileKinds = 0u, gTileSeed = 0u, gTileMinDepth = 0xFFFFFFFFu;

// fetchWithDepth() (edtsm_screen.glsl) with the bounds known per row: depth −1 off the screen.
void fetchColumn(ivec2 pixel, out vec2 column[3]) {
  const bool columnInside = pixel.x >= 0 && pixel.x < gSize.x;
  for (int dy = -1; dy <= 1; ++dy)
    column[dy + 1] = columnInside && gRowInside[dy + 1] ? imageLoad(uHardImage, pixel + ivec2(0, dy)).xy : vec2(0.0, -1.0);
}

void featureTransformRowBegin(int y) {
  gSize = textureSize(uHard, 0);
  for (int dy = -1; dy <= 1; ++dy) gRowInside[dy + 1] = y + dy >= 0 && y + dy < gSize.y;
  fetchColumn(ivec2(-1, y), gAt);  // off the screen: depth −1
  fetchColumn(ivec2(0, y), gAfter);
}

bool featureTransformIsSeed(ivec2 pixel) {
  gBefore = gAt;
  gAt = gAfter;
  fetchColumn(pixel + ivec2(1, 0), gAfter);
  const vec2 centre = gAt[1];
  bool seed = false;
  for (int dy = 0; dy < 3; ++dy)
    seed = seed || seedNeighbour(centre, gBefore[dy]) || seedNeighbour(centre, gAt[dy]) ||
           seedNeighbour(centre, gAfter[dy]);
  gTileKinds |= intensityKind(centre);
  if (seed) gTileSeed = 1u;
  if (!(centre.y < 0.0)) gTileMinDepth = min(gTileMinDepth, floatBitsToUint(centre.y));
  return seed;
}

// One atomic of each record per row of a tile.
const int kRowSpan = kBandTile;
void featureTransformSpanEnd(ivec2 pixel) {
  const ivec2 tile = pixel / kBandTile;
  if (gTileKinds != 0u) imageAtomicOr(uTileKinds, pixel / kTile, gTileKinds);
  if (gTileSeed != 0u) imageAtomicOr(uTileSeeds, tile, 1u);
  if (gTileMinDepth != 0xFFFFFFFFu) imageAtomicMin(uTileMinDepth, tile, gTileMinDepth);
  gTileKinds = 0u;
  gTileSeed = 0u;
  gTileMinDepth = 0xFFFFFFFFu;
}

#include "techniques/distance_transform/feature_transform_row_sweep.glsl"

void main() { featureTransformRow(); }
