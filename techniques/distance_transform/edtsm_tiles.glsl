// What EDTSM's fused passes record per 16×16 tile of the screen: the mean filter's kinds
// (edtsm_filter_tiles.h), the penumbra band's seeds and depths (edtsm_penumbra_band.h).
const int kTile = 16;      // FilterTiles::kTile, = kBandTile (edtsm_seeds.comp records both per span)
const int kBandTile = 16;  // PenumbraBand::kTile, a multiple of the 8 lanes of a SIMD vector

// The mean filter's kinds (edtsm_filter_tiles.h) of one (intensity, depth or −1) texel:
// none for depth −1, bit 0 exactly +0, bit 1 exactly 1, bit 2 anything else.
uint intensityKind(vec2 v) {
  if (v.y < 0.0) return 0u;
  return floatBitsToUint(v.x) == 0u ? 1u : v.x == 1.0 ? 2u : 4u;
}
