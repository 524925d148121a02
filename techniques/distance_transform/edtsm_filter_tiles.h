#pragma once
// Where EDTSM's mean filter (EDTSM* §3.4) can change a pixel, found tile by tile so that
// its two dispatches run on those tiles only. The filter averages, along a row and then a
// column, the receivers of a window at most max_filter_radius pixels to each side. Where
// every receiver in the (2 radius + 1)² box around a pixel has the same intensity, 0 or 1
// (RBSM's hard answer, no penumbra), both averages are that value exactly: a sum of n
// zeros or ones is exact in float, and n / n is 1. Such pixels keep the penumbra's
// intensity, copied; the output is the same as two full-screen draws, bit for bit. The
// first (row) pass needs only the row to agree: where it does, its result is the
// intensity itself, so the second (column) pass reads the copy there unchanged.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"

namespace testbed::distance_transform {

class FilterTiles {
 public:
  // kTile of edtsm_tiles.glsl; edtsm_mean_filter.comp's workgroup is one tile.
  static constexpr int kTile = 16;

  // Makes the kinds image (R32UI, a tile per texel: bit 0 a receiver at exactly +0, bit 1
  // at 1, bit 2 any other value) for `size` pixels, clears it and binds it at
  // kTileKindsImageUnit for a shader to OR into (edtsm_seeds.comp, edtsm_penumbra.comp).
  void begin(glm::ivec2 size);
  // Once the kinds are complete (and made visible to texel fetches): lists the tiles with
  // a pixel whose window of `radius` pixels to each side holds more than one kind, or one
  // other than 0 and 1: along x for the row pass, in the box for the column pass.
  void findTiles(int radius);
  // Runs edtsm_mean_filter.comp (`program`, its other inputs bound) over the row pass's
  // tiles (`columns` false) or the column pass's, writing `target` (bound at
  // kEdtsmOutputImageUnit as `format`); makes the writes visible to fetches, blits and read-backs.
  void dispatch(const Program& program, const Texture& target, GLenum format, bool columns) const;

 private:
  Program listProgram_;
  Texture kinds_;
  Buffer lists_;  // edtsm_filter_tiles.comp's layout
  glm::ivec2 tiles_{0};
};

}  // namespace testbed::distance_transform
