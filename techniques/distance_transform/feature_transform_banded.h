#pragma once
// The exact Euclidean feature transform of feature_transform.h (the same seed for every
// pixel: the least (distance², row, column)), shaped for a GPU as the parallel banding
// algorithm is: every phase cut into bands so that a screen keeps tens of thousands of
// invocations busy, where FeatureTransformPass runs one invocation per row, then one per
// column. Cao, Tang, Mukherjee & Leong, "Parallel Banding Algorithm to Compute Exact
// Distance Transform with the GPU", I3D 2010, §3:
//   phase 1  per row, bands of columns: each band's first and last seed, carried across the
//            bands of the row, then each band's sweeps (the nearest seed column of a pixel);
//   phase 2  per column, bands of rows: each band's proximate sites (its stack of the
//            lower envelope of the parabolas), then adjacent bands' stacks merged pairwise,
//            log2(bands) rounds, and where each band's first row lands on the merged list;
//   phase 3  per column, bands of rows: each band colours its rows along the list.
// The passes are integer-exact like FeatureTransformPass's (feature_transform_band.glsl).
// At the default 8 pixels a band, 1280×720 dispatches 115 200 invocations in each band step
// (phase 1's carry is one invocation a row, as the paper's; phase 2's merges halve from
// 57 600).
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/gl/objects.h"
#include "testbed/technique/declaration.h"

namespace testbed {

class BandedFeatureTransformPass {
 public:
  static constexpr int kMaxExtent = 16384;  // int32-exact, as FeatureTransformPass's
  static constexpr int kDefaultBand = 8;

  // `bandPixels`: pixels a band in every phase (1 to the image's side; the result does not
  // depend on it).
  explicit BandedFeatureTransformPass(int bandPixels = kDefaultBand);
  // Its per-band images, booked under this (its per-pixel ones under "edt-scratch", as
  // FeatureTransformPass's).
  static ResourceDeclaration declaredBands(int bandPixels = kDefaultBand);
  // As FeatureTransformPass::run(seeds, size). `afterPhase`, if set, is called with 1, 2 and
  // 3 after each phase's dispatches (to count each phase's work).
  void run(const Texture& seeds, glm::ivec2 size, const std::function<void(int phase)>& afterPhase = {});

  // RG32I: (x, y) of each pixel's nearest seed, or (-1, -1); as FeatureTransformPass's.
  const Texture& nearest() const { return nearest_; }
  std::vector<glm::ivec2> readNearest() const;

 private:
  void prepare(glm::ivec2 size);
  void phase1(const Texture& seeds);
  void phase2();
  void phase3();
  void dispatch(const Program& program, int x, int y) const;  // x × y invocations, 8×8 groups

  int band_;
  Program bandSeeds_, carry_, rowSweep_, proximate_, merge_, starts_, colour_;
  glm::ivec2 size_{0}, rowBands_{0}, columnBands_{0};
  Texture nearest_, bandSeedsImage_, bandCarry_, rowNearest_, links_, bandEnds_, bandStart_;
};

}  // namespace testbed
