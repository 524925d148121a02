#pragma once
// Temporal error metrics of a technique's visibility over a sequence of frames against the
// ground truth's (docs/motion.md, "Temporal metrics"). Frames are streamed: the accumulator
// keeps only the previous frame, so its memory does not grow with the number of images.
//
// Receivers are the pixels where the ground truth is not NaN (as in metrics.h); binary
// state: lit <=> value >= 0.5. Frame t is compared with the *held view* of frame t-1: the
// scene as it was at t-1 (light, objects and every set-up fitted to them) seen through
// frame t's camera. Both renders share one camera, so pixel p of one is pixel p of the
// other: a pair needs no reprojection. Pixel p forms a stable pair when it is a receiver
// in both renders and their G-buffer positions there are equal (bit for bit, coverage
// included); a receiver whose positions differ sees another surface point in the other
// render (a moving object, or what it uncovers) and is counted as moved, not paired.
// Where the camera did not move the held view is frame t-1 itself.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/io/image_io.h"

namespace testbed {

// One render, all images top-down and of one size.
struct TemporalFrame {
  int frame = 0;                 // the scene's frame number, carried into the series
  const ImageF& visibility;      // technique, one channel, NaN where no receiver
  const ImageF& groundTruth;     // one channel, NaN where no receiver
  const ImageF& positions;       // G-buffer: xyz world position, w coverage (FrameRunner::positions())
  glm::mat4 viewProjection{1};   // the camera's, world -> clip
};

// Figures of one frame pair (held view of t-1, t).
struct FramePairTemporal {
  int frame = 0;                  // t, the later frame's number
  double flicker = 0;             // mean over its stable pairs of |(V_t - V_held) - (G_t - G_held)|
  double crawlPct = 0;            // % of its stable pairs: V's state changes, G's does not
  double crawlMissedPct = 0;      // % of its stable pairs: G's state changes, V's does not
  std::size_t stablePairs = 0;    // the denominator; 0 gives 0 for the three above
  std::size_t movedPixels = 0;    // receivers in either render whose positions differ: not paired
  bool heldRender = false;        // the held view was rendered apart (the camera moved)
};

struct TemporalMetrics {
  double flicker = 0;             // pooled over every stable pair of every frame pair
  double crawlPct = 0;
  double crawlMissedPct = 0;
  std::size_t stablePairs = 0;    // pooled denominator
  std::size_t movedPixels = 0;    // summed over frame pairs
  int framePairs = 0;             // frames added - 1 (0 before the second frame)
  int heldRenders = 0;            // frame pairs whose held view was rendered apart
  std::vector<FramePairTemporal> series;  // one per frame pair, in order
};

class TemporalAccumulator {
 public:
  // Validates the frame (one-channel V and G, four-channel positions, one size for all and
  // for every earlier frame, V not NaN on a receiver, coverage on every receiver, a finite
  // view-projection) and returns the pair it forms (none for the first frame). `held` is
  // the held view of the previous frame, rendered through this frame's camera (its
  // viewProjection equal to the frame's); without it the previous frame is the held view,
  // which needs the previous frame's camera to be this one. Throws std::invalid_argument
  // naming the image and, where there is one, the pixel as (x, y) from the top row; a
  // frame that throws is not added.
  std::optional<FramePairTemporal> addFrame(const TemporalFrame& frame, const TemporalFrame* held = nullptr);

  const TemporalMetrics& result() const { return result_; }
  int frames() const { return frames_; }

 private:
  struct Previous {
    ImageF visibility, groundTruth, positions;
    glm::mat4 viewProjection{1};
  };
  FramePairTemporal compare(const TemporalFrame& held, const TemporalFrame& frame);
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
