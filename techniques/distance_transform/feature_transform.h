#pragma once
// Exact Euclidean feature transform of a screen-space seed mask on the GPU: for every pixel,
// the integer coordinates of its nearest seed (ties broken either way), or (-1, -1) when
// the image has no seed. EDTSM (EDTSM* §3.3) needs the seed itself, not only the
// distance, to read that seed's world position from the G-buffer.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
//
// Separable and linear time (Meijster, Roerdink & Hesselink 2000; Felzenszwalb &
// Huttenlocher 2012): pass 1 finds, per row, the nearest seed column; pass 2 takes, per
// column, the lower envelope of the parabolas (y - y')² + dx(y')² over the rows y'. All
// arithmetic is in int32, so the result is exact, unlike jump flooding.
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/gl/objects.h"

namespace testbed {

class FeatureTransformPass {
 public:
  // Largest side handled: keeps every squared distance and envelope intersection in int32.
  static constexpr int kMaxExtent = 16384;

  // `seeds`: a float-sampled texture (R8, R32F, ...), a seed where the red channel > 0.5;
  // only its texels [0, size) are read. Allocates (and books in the current
  // GpuMemoryLedger) the output and scratch buffers when `size` changes.
  void run(const Texture& seeds, glm::ivec2 size);
  // The same transform with both passes the caller's: `rows`, a compute program built on
  // feature_transform_row_sweep.glsl that tells the seeds itself, and `columns`, one built
  // on feature_transform_envelope.glsl that consumes each pixel's nearest seed itself, so
  // nearest() is not written. The caller binds their textures, images and uniforms; uSize
  // and the buffers are bound here, and image writes are made visible as run()'s are.
  // `between`, if set, runs after the row pass's writes are made visible, before `columns`.
  void run(glm::ivec2 size, const Program& rows, const Program& columns, const std::function<void()>& between = {});

  // RG32I, `size` texels: (x, y) texel coordinates of the nearest seed, or (-1, -1). Valid
  // after the first run(); its writes are made visible to texel fetches, image loads and read-backs.
  const Texture& nearest() const { return nearest_; }
  glm::ivec2 size() const { return size_; }

  // Reads nearest() back, rows bottom-up (texel (x, y) at index y * width + x).
  std::vector<glm::ivec2> readNearest() const;

 private:
  // Checks `size` and (re)allocates the scratch buffers for it.
  void prepare(glm::ivec2 size);
  void rows(const Program& rows);        // pass 1 into rowNearest_
  void columns(const Program& columns);  // pass 2 from it

  Program rowsProgram_, columnsProgram_;
  glm::ivec2 size_{0};
  Texture nearest_;
  // Images rather than shader storage buffers: on llvmpipe an image store costs about half
  // the instructions of a buffer store, and these two take one or more per pixel. Bound at
  // the units of feature_transform_units.glsl.
  Texture rowNearest_;  // R32I, a texel per pixel: nearest seed column in the same row, -1 if none
  Texture envelope_;    // RG32I, a texel per pixel: pass 2's parabola stacks (row, first row it wins)
};

}  // namespace testbed
