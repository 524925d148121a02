#pragma once
// Where EDTSM's mean filter (EDTSM* §3.4) can change a pixel, found tile by tile so that
// its two draws run on those tiles only. The filter averages, along a row and then a
// column, the receivers of a window at most max_filter_radius pixels to each side. Where
// every receiver in the (2 radius + 1)² box around a pixel has the same intensity, 0 or 1
// (RBSM's hard answer, no penumbra), both averages are that value exactly: a sum of n
// zeros or ones is exact in float, and n / n is 1. Such pixels keep the penumbra's
// intensity, copied; the output is the same as two full-screen draws, bit for bit. The
// first (row) draw needs only the row to agree: where it does, its result is the
// intensity itself, so the second (column) draw reads the copy there unchanged.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"

namespace testbed::distance_transform {

class FilterTiles {
 public:
  static constexpr int kTile = 32;  // kTile of edtsm_penumbra.comp and edtsm_filter_tile.vert

  // Makes the kinds image (R32UI, a tile per texel: bit 0 a receiver at exactly +0, bit 1
  // at 1, bit 2 any other value) for `size` pixels, clears it and binds it at image unit
  // `unit` for a shader to OR into (edtsm_penumbra.comp).
  void begin(glm::ivec2 size, GLuint unit);
  // Draws `program` (vertex stage edtsm_filter_tile.vert) into `target` over the tiles
  // with a pixel whose window of `reach` pixels to each side (along x, along y) holds
  // more than one kind, or one other than 0 and 1. The kinds must be complete (and made
  // visible to texel fetches).
  void draw(const Program& program, const Framebuffer& target, glm::ivec2 size, glm::ivec2 reach) const;

 private:
  Texture kinds_;
  VertexArray empty_;
  glm::ivec2 tiles_{0};
};

}  // namespace testbed::distance_transform
