#pragma once
// Temporal error metrics of a technique's visibility over a sequence of frames against the
// ground truth's (docs/motion.md, "Temporal metrics"). Frames are streamed: the accumulator
// keeps only the previous frame, so its memory does not grow with the number of images.
//
// Receivers are the pixels where the ground truth is not NaN (as in metrics.h); binary
// state: lit <=> value >= 0.5. A pixel p of frame t and a pixel q of frame t-1 form a
// surface-stable pair when both are receivers and see the same surface point:
//   - static camera (the two view-projections are equal): q = p;
//   - moving camera: q is the pixel of frame t-1 nearest to where p's world position
//     projects in frame t-1, and q's world position lies within `toleranceFootprints`
//     pixel footprints of p's, the footprint being the world-space side of one pixel of
//     frame t-1 at that depth (perpendicular to the view ray). Off-screen, behind the
//     camera or farther (a disocclusion: q sees another surface) -> no pair.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/io/image_io.h"

namespace testbed {

struct TemporalOptions {
  // Nearest-pixel reprojection lands up to half a pixel off in x and y; on a surface seen
  // at angle theta from its normal that is up to 0.5 * sqrt(1 + 1/cos^2 theta) footprints
  // of world distance. 2 footprints accept every surface up to theta = 75 degrees and
  // reject depth gaps wider than two pixels, the disocclusions reprojection must drop.
  double toleranceFootprints = 2.0;
};

// One frame of a sequence, all images top-down and of one size.
struct TemporalFrame {
  int frame = 0;                 // the scene's frame number, carried into the series
  const ImageF& visibility;      // technique, one channel, NaN where no receiver
  const ImageF& groundTruth;     // one channel, NaN where no receiver
  const ImageF& positions;       // G-buffer: xyz world position, w coverage (FrameRunner::positions())
  glm::mat4 viewProjection{1};   // the camera's, world -> clip
};

// Figures of one pair of consecutive frames (t-1, t).
struct FramePairTemporal {
  int frame = 0;                  // t, the later frame's number
  double flicker = 0;             // mean over its stable pairs of |(V_t - V_t-1) - (G_t - G_t-1)|
  double crawlPct = 0;            // % of its stable pairs: V's state changes, G's does not
  double crawlMissedPct = 0;      // % of its stable pairs: G's state changes, V's does not
  std::size_t stablePairs = 0;    // the denominator; 0 gives 0 for the three above
};

struct TemporalMetrics {
  double flicker = 0;             // pooled over every stable pair of every frame pair
  double crawlPct = 0;
  double crawlMissedPct = 0;
  std::size_t stablePairs = 0;    // pooled denominator
  int framePairs = 0;             // frames added - 1 (0 before the second frame)
  std::vector<FramePairTemporal> series;  // one per frame pair, in order
};

class TemporalAccumulator {
 public:
  explicit TemporalAccumulator(TemporalOptions options = {});

  // Validates the frame (one-channel V and G, four-channel positions, one size for all and
  // for every earlier frame, V not NaN on a receiver, coverage on every receiver, a finite
  // view-projection) and returns the pair it forms with the previous frame (none for the
  // first). Throws std::invalid_argument naming the image and, where there is one, the
  // pixel as (x, y) from the top row; a frame that throws is not added.
  std::optional<FramePairTemporal> addFrame(const TemporalFrame& frame);

  const TemporalMetrics& result() const { return result_; }
  int frames() const { return frames_; }

 private:
  struct Previous {
    ImageF visibility, groundTruth, positions;
    glm::mat4 viewProjection{1};
  };
  TemporalOptions options_;
  std::optional<Previous> previous_;
  TemporalMetrics result_;
  int frames_ = 0;
  double flickerSum_ = 0;
  std::size_t crawls_ = 0, crawlsMissed_ = 0;
};

// A per-frame series summarized: mean, 95th percentile (nearest rank, the value at index
// ceil(0.95 n) - 1 of the sorted values, as boundary_px in metrics.h) and maximum. An
// empty series gives zeros; a NaN value throws std::invalid_argument.
struct SeriesSummary {
  double mean = 0, p95 = 0, max = 0;
  std::size_t count = 0;
};
SeriesSummary summarizeSeries(const std::vector<double>& values);

}  // namespace testbed
