#pragma once
// Where EDTSM's eq. 8 (EDTSM* §3.3) can change a pixel, so that the feature transform's
// column pass runs its envelope and eq. 8 on those rows only; everywhere else the intensity
// is RBSM's hard visibility, copied. Same output as the exact transform everywhere, bit for
// bit:
// - eq. 8 uses the nearest seed q only when its world distance d to the receiver p is at
//   most P/2. A world segment of length d whose ends lie on the screen projects to at most
//   d · F · k / (Z_p − d) pixels, F the pixels per unit of tan (max of W·P00/2, H·P11/2),
//   k = sqrt(1 + 1/P00² + 1/P11²) the largest stretch of the perspective's Jacobian on the
//   screen, Z_p the receiver's eye depth (no point of the segment is nearer than Z_p − d).
//   So every seed that eq. 8 can use lies within R(p) pixels (that bound with margins for
//   float rounding; unbounded where Z_p <= P/2), and any seed farther than R(p) leaves the
//   pixel's hard answer, whichever it is.
// - The transform over the rows within R of a run of tiles, keeping only rows whose
//   nearest seed (pass 1, exact) is within R columns, R the largest R(p) of the run, holds
//   every seed within R(p) of each of its pixels and breaks ties as the full transform
//   does (least distance, then least row, then least column): where the nearest seed is
//   within R(p) both find it; elsewhere both leave the hard answer.
// - A tile needs that work only if a tile holding a seed lies within ceil(R / 16) tiles,
//   R from its nearest receiver (least camera depth), tiles of 16×16 pixels.
// The feature transform's row pass (edtsm_seeds.comp) records, per tile, whether it holds a
// seed, its least receiver depth and the filter's kinds of the hard visibility; a
// one-invocation-per-tile-column pass (edtsm_penumbra_band.comp) turns them into runs of
// tile rows with their R for the column pass (edtsm_penumbra.comp).
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"

namespace testbed::distance_transform {

class PenumbraBand {
 public:
  static constexpr int kTile = 16;  // kBandTile of edtsm_tiles.glsl

  // Makes (and books) the per-tile images and the runs for `size` pixels, clears them and
  // binds the images for the row pass: seeds at image unit 2, least depth at unit 3.
  void begin(glm::ivec2 size);
  // After the row pass: the runs for penumbra P and the camera's `projection` (a
  // perspective), bound at storage buffer 2 for the column pass.
  void findRuns(float penumbra, const glm::mat4& projection);
  // Unbinds what begin() and findRuns() bound.
  void end() const;

 private:
  Program runsProgram_;
  Texture seeds_, minDepth_;
  Buffer runs_;
  glm::ivec2 size_{0}, tiles_{0};
};

}  // namespace testbed::distance_transform
