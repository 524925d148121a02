// What EDTSM's fused passes record per 32×32 tile of the screen (edtsm_penumbra_band.h,
// edtsm_filter_tiles.h), and the band of screen distance within which eq. 8 can use a seed.
const int kTile = 32;  // FilterTiles::kTile, PenumbraBand::kTile

// The mean filter's kinds (edtsm_filter_tiles.h) of one (intensity, depth or −1) texel:
// none for depth −1, bit 0 exactly +0, bit 1 exactly 1, bit 2 anything else.
uint intensityKind(vec2 v) {
  if (v.y < 0.0) return 0u;
  return floatBitsToUint(v.x) == 0u ? 1u : v.x == 1.0 ? 2u : 4u;
}
