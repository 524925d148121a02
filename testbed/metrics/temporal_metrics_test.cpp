// Temporal metrics on hand-made sequences whose answers are known by construction.
#include "testbed/metrics/temporal_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace testbed {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

ImageF makeImage(int w, int h, const std::function<float(int, int)>& value) {
  ImageF image{w, h, 1, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.pixels.push_back(value(x, y));
  return image;
}

// Positions for a static camera: the metrics pair pixels by index, so any covered point will do.
ImageF flatPositions(int w, int h) {
  ImageF image{w, h, 4, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.pixels.insert(image.pixels.end(), {float(x), float(y), 0.f, 1.f});
  return image;
}

TemporalMetrics run(const std::vector<std::pair<ImageF, ImageF>>& frames, const ImageF& positions,
                    const glm::mat4& viewProjection = glm::mat4(1)) {
  TemporalAccumulator accumulator;
  int index = 0;
  for (const auto& [v, g] : frames)
    accumulator.addFrame({.frame = index++, .visibility = v, .groundTruth = g, .positions = positions,
                          .viewProjection = viewProjection});
  return accumulator.result();
}

void expectZero(const TemporalMetrics& m) {
  EXPECT_EQ(m.flicker, 0.0);
  EXPECT_EQ(m.crawlPct, 0.0);
  EXPECT_EQ(m.crawlMissedPct, 0.0);
  for (const FramePairTemporal& pair : m.series) {
    EXPECT_EQ(pair.flicker, 0.0);
    EXPECT_EQ(pair.crawlPct, 0.0);
    EXPECT_EQ(pair.crawlMissedPct, 0.0);
  }
}

// A shadow edge sweeping across a 12x8 image, one column per frame, with soft values.
ImageF sweepingEdge(int t) {
  return makeImage(12, 8, [t](int x, int y) {
    if (x == 11 && y == 7) return kNaN;  // a pixel without receiver
    return x < 2 + t ? 1.f : (x == 2 + t ? 0.3f : 0.f);
  });
}

TEST(TemporalMetrics, GroundTruthAgainstItselfIsZero) {
  std::vector<std::pair<ImageF, ImageF>> frames;
  for (int t = 0; t < 5; ++t) frames.emplace_back(sweepingEdge(t), sweepingEdge(t));
  const TemporalMetrics m = run(frames, flatPositions(12, 8));
  expectZero(m);
  EXPECT_EQ(m.framePairs, 4);
  EXPECT_EQ(m.stablePairs, 4u * (12 * 8 - 1));
  ASSERT_EQ(m.series.size(), 4u);
  EXPECT_EQ(m.series[3].frame, 4);
}

TEST(TemporalMetrics, StaticSequenceIsZeroEvenWithErrors) {
  // The technique is wrong (a shifted, softened edge) but wrong the same way every frame.
  const ImageF g = sweepingEdge(2);
  const ImageF v = makeImage(12, 8, [&](int x, int y) { return std::isnan(g.at(x, y)) ? kNaN : (x < 6 ? 0.8f : 0.1f); });
  const TemporalMetrics m = run({{v, g}, {v, g}, {v, g}}, flatPositions(12, 8));
  expectZero(m);
  EXPECT_EQ(m.stablePairs, 2u * (12 * 8 - 1));
}

TEST(TemporalMetrics, HandBuilt4x4Sequence) {
  // G0: lit for x < 2, no receiver at (3,3). G1: lit for x < 3. G2 = G1 without a receiver
  // at (0,0). V0 = G0 but 0.6 at (2,0); V1: 0.75 down column 2, 0.4 at (1,1); V2 = V1.
  const ImageF g0 = makeImage(4, 4, [](int x, int y) { return x == 3 && y == 3 ? kNaN : (x < 2 ? 1.f : 0.f); });
  const ImageF g1 = makeImage(4, 4, [](int x, int) { return x < 3 ? 1.f : 0.f; });
  const ImageF g2 = makeImage(4, 4, [&](int x, int y) { return x == 0 && y == 0 ? kNaN : g1.at(x, y); });
  const ImageF v0 = makeImage(4, 4, [&](int x, int y) { return x == 2 && y == 0 ? 0.6f : g0.at(x, y); });
  const ImageF v1 = makeImage(4, 4, [](int x, int y) {
    if (x == 1 && y == 1) return 0.4f;
    return x < 2 ? 1.f : (x == 2 ? 0.75f : 0.f);
  });
  const ImageF v2 = makeImage(4, 4, [&](int x, int y) { return x == 0 && y == 0 ? kNaN : v1.at(x, y); });
  const TemporalMetrics m = run({{v0, g0}, {v1, g1}, {v2, g2}}, flatPositions(4, 4));

  // One camera and equal positions throughout: the previous frame is the held view.
  // Frame pair 0->1, 15 pixels receivers in both ((3,3) is not in frame 0):
  //   (1,1): dv = 0.4 - 1, dg = 0            -> 0.6; V's state changes, G's not: crawl
  //   (2,0): dv = 0.75 - 0.6, dg = 1         -> 0.85; G's state changes, V's not: missed
  //   (2,1..3): dv = 0.75, dg = 1            -> 0.25 each; both change: neither
  //   every other pixel                      -> 0
  // Frame pair 1->2: 15 pixels ((0,0) is not in frame 2), nothing changes.
  ASSERT_EQ(m.series.size(), 2u);
  EXPECT_EQ(m.series[0].stablePairs, 15u);
  EXPECT_NEAR(m.series[0].flicker, 2.2 / 15, 1e-6);
  EXPECT_NEAR(m.series[0].crawlPct, 100.0 / 15, 1e-12);
  EXPECT_NEAR(m.series[0].crawlMissedPct, 100.0 / 15, 1e-12);
  EXPECT_EQ(m.series[0].movedPixels, 1u);  // (3,3): a receiver in frame 1 only
  EXPECT_EQ(m.series[1].stablePairs, 15u);
  EXPECT_EQ(m.series[1].movedPixels, 1u);  // (0,0): a receiver in frame 1 only
  EXPECT_EQ(m.series[1].flicker, 0.0);
  EXPECT_EQ(m.series[1].crawlPct, 0.0);
  EXPECT_EQ(m.stablePairs, 30u);
  EXPECT_EQ(m.framePairs, 2);
  EXPECT_NEAR(m.flicker, 2.2 / 30, 1e-6);
  EXPECT_NEAR(m.crawlPct, 100.0 / 30, 1e-12);
  EXPECT_NEAR(m.crawlMissedPct, 100.0 / 30, 1e-12);
}

// A camera pan: frame 0 at camera A, frame 1 at camera B, with the held view of frame 0
// (frame 0's scene through camera B) given. The pair is the held view against frame 1,
// pixel by pixel; how frame 0 looked through A does not enter it.
glm::mat4 cameraAt(float x) {
  return glm::ortho(-2.f, 2.f, -1.f, 1.f, 0.1f, 200.f) *
         glm::lookAt(glm::vec3(x, 0, 100), glm::vec3(x, 0, 0), glm::vec3(0, 1, 0));
}

TEST(TemporalMetrics, HeldViewIsComparedPixelByPixelAndMovedPointsAreDropped) {
  // 4x2. Frame 0 through camera A: anything (here its own edge, badly placed).
  const ImageF p = flatPositions(4, 2);
  const ImageF a = makeImage(4, 2, [](int x, int) { return x < 1 ? 1.f : 0.f; });
  // Held view (frame 0's scene through B): G lit for x < 2; V = G but 0.3 at (0,1).
  const ImageF hg = makeImage(4, 2, [](int x, int) { return x < 2 ? 1.f : 0.f; });
  const ImageF hv = makeImage(4, 2, [&](int x, int y) { return x == 0 && y == 1 ? 0.3f : hg.at(x, y); });
  // Frame 1 through B: the light moved, G lit for x < 3. V: 0.9 at (2,0), 0 at (2,1) (the
  // edge does not follow there), and an object moved at (3,1): its position changed, so
  // the wrong 1 there is not a pair (it would be a crawl).
  const ImageF g1 = makeImage(4, 2, [](int x, int) { return x < 3 ? 1.f : 0.f; });
  const ImageF v1 = makeImage(4, 2, [&](int x, int y) {
    if (x == 2) return y == 0 ? 0.9f : 0.f;
    if (x == 3 && y == 1) return 1.f;
    return hv.at(x, y);
  });
  ImageF p1 = p;
  p1.pixels[(1 * 4 + 3) * 4 + 2] = 0.25f;  // (3,1)'s z

  TemporalAccumulator accumulator;
  EXPECT_FALSE(accumulator.addFrame({.frame = 0, .visibility = a, .groundTruth = a, .positions = p,
                                     .viewProjection = cameraAt(0)}));
  const TemporalFrame held{.frame = 1, .visibility = hv, .groundTruth = hg, .positions = p,
                           .viewProjection = cameraAt(1)};
  const auto pair = accumulator.addFrame(
      {.frame = 1, .visibility = v1, .groundTruth = g1, .positions = p1, .viewProjection = cameraAt(1)}, &held);
  ASSERT_TRUE(pair);
  // 8 receivers, (3,1) moved: 7 pairs.
  //   (2,0): dv = 0.9, dg = 1  -> 0.1; both change state
  //   (2,1): dv = 0,   dg = 1  -> 1;   G changes, V not: missed
  //   (0,1): dv = 0,   dg = 0  -> 0;   the held view's own error stays: no flicker
  EXPECT_EQ(pair->stablePairs, 7u);
  EXPECT_EQ(pair->movedPixels, 1u);
  EXPECT_TRUE(pair->heldRender);
  EXPECT_NEAR(pair->flicker, 1.1 / 7, 1e-6);
  EXPECT_EQ(pair->crawlPct, 0.0);
  EXPECT_NEAR(pair->crawlMissedPct, 100.0 / 7, 1e-12);
  EXPECT_EQ(accumulator.result().heldRenders, 1);
  EXPECT_EQ(accumulator.result().movedPixels, 1u);

  // The next frame at the same camera pairs with frame 1 itself: nothing changes, 0.
  const auto still = accumulator.addFrame(
      {.frame = 2, .visibility = v1, .groundTruth = g1, .positions = p1, .viewProjection = cameraAt(1)});
  ASSERT_TRUE(still);
  EXPECT_EQ(still->stablePairs, 8u);
  EXPECT_EQ(still->flicker, 0.0);
  EXPECT_FALSE(still->heldRender);
  EXPECT_EQ(accumulator.result().heldRenders, 1);
  EXPECT_EQ(accumulator.result().framePairs, 2);
  EXPECT_NEAR(accumulator.result().flicker, 1.1 / 15, 1e-6);
}

TEST(TemporalMetrics, ACameraMoveReadsZeroWhenTheHeldViewIsTheFrame) {
  // Only the camera moved: the held view is the frame itself, however wrong V is and
  // however far the camera went, so every figure is 0.
  const ImageF g = sweepingEdge(3), p = flatPositions(12, 8);
  const ImageF v = makeImage(12, 8, [&](int x, int y) { return std::isnan(g.at(x, y)) ? kNaN : (x % 3 == 0 ? 0.7f : 0.2f); });
  TemporalAccumulator accumulator;
  for (int k = 0; k < 4; ++k) {
    const TemporalFrame frame{.frame = k, .visibility = v, .groundTruth = g, .positions = p,
                              .viewProjection = cameraAt(float(k * k))};
    accumulator.addFrame(frame, k == 0 ? nullptr : &frame);
  }
  expectZero(accumulator.result());
  EXPECT_EQ(accumulator.result().heldRenders, 3);
  EXPECT_EQ(accumulator.result().stablePairs, 3u * (12 * 8 - 1));
  EXPECT_EQ(accumulator.result().movedPixels, 0u);
}

TEST(TemporalMetrics, PositionsMustMatchBitForBit) {
  // One ulp in one coordinate is another surface point: the pixel is moved, not paired.
  const ImageF g = sweepingEdge(1), p = flatPositions(12, 8);
  ImageF nudged = p;
  float& z = nudged.pixels[(2 * 12 + 5) * 4 + 2];
  z = std::nextafter(z, 1.f);
  TemporalAccumulator accumulator;
  accumulator.addFrame({.frame = 0, .visibility = g, .groundTruth = g, .positions = p});
  const auto pair = accumulator.addFrame({.frame = 1, .visibility = g, .groundTruth = g, .positions = nudged});
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->movedPixels, 1u);
  EXPECT_EQ(pair->stablePairs, std::size_t(12 * 8 - 2));
}

TEST(TemporalMetrics, AMovedCameraNeedsTheHeldViewOfThatCamera) {
  const ImageF g = sweepingEdge(0), p = flatPositions(12, 8);
  TemporalAccumulator accumulator;
  const TemporalFrame first{.frame = 0, .visibility = g, .groundTruth = g, .positions = p, .viewProjection = cameraAt(0)};
  EXPECT_THROW(accumulator.addFrame(first, &first), std::invalid_argument);  // nothing to hold yet
  accumulator.addFrame(first);
  const TemporalFrame moved{.frame = 1, .visibility = g, .groundTruth = g, .positions = p, .viewProjection = cameraAt(1)};
  EXPECT_THROW(accumulator.addFrame(moved), std::invalid_argument);          // no held view
  EXPECT_THROW(accumulator.addFrame(moved, &first), std::invalid_argument);  // held through another camera
  const ImageF small = makeImage(4, 4, [](int, int) { return 1.f; });
  const ImageF smallPositions = flatPositions(4, 4);
  const TemporalFrame smallHeld{.frame = 1, .visibility = small, .groundTruth = small, .positions = smallPositions,
                                .viewProjection = cameraAt(1)};
  EXPECT_THROW(accumulator.addFrame(moved, &smallHeld), std::invalid_argument);  // held of another size
  EXPECT_EQ(accumulator.frames(), 1);
  EXPECT_EQ(accumulator.result().framePairs, 0);
  EXPECT_TRUE(accumulator.addFrame(moved, &moved));
}

TEST(TemporalMetrics, BadInputsThrowAndAreNotAdded) {
  const ImageF g = sweepingEdge(0), p = flatPositions(12, 8);
  TemporalAccumulator accumulator;
  accumulator.addFrame({.frame = 0, .visibility = g, .groundTruth = g, .positions = p});
  const ImageF small = makeImage(4, 4, [](int, int) { return 1.f; });
  EXPECT_THROW(accumulator.addFrame({.frame = 1, .visibility = small, .groundTruth = g, .positions = p}),
               std::invalid_argument);
  // A whole frame of another size than the previous one.
  EXPECT_THROW(accumulator.addFrame({.frame = 1, .visibility = small, .groundTruth = small, .positions = flatPositions(4, 4)}),
               std::invalid_argument);
  EXPECT_THROW(accumulator.addFrame({.frame = 1, .visibility = g, .groundTruth = g, .positions = g}),
               std::invalid_argument);
  ImageF lost = g;
  lost.pixels[5] = kNaN;
  EXPECT_THROW(accumulator.addFrame({.frame = 1, .visibility = lost, .groundTruth = g, .positions = p}),
               std::invalid_argument);
  ImageF uncovered = p;
  uncovered.pixels[3] = 0.f;
  EXPECT_THROW(accumulator.addFrame({.frame = 1, .visibility = g, .groundTruth = g, .positions = uncovered}),
               std::invalid_argument);
  glm::mat4 broken(1);
  broken[3][0] = std::numeric_limits<float>::infinity();
  EXPECT_THROW(accumulator.addFrame({.frame = 1, .visibility = g, .groundTruth = g, .positions = p, .viewProjection = broken}),
               std::invalid_argument);
  EXPECT_EQ(accumulator.frames(), 1);
  EXPECT_EQ(accumulator.result().framePairs, 0);
}

TEST(TemporalMetrics, SeriesSummary) {
  std::vector<double> values;
  for (int i = 20; i >= 1; --i) values.push_back(i);
  const SeriesSummary s = summarizeSeries(values);
  EXPECT_EQ(s.count, 20u);
  EXPECT_DOUBLE_EQ(s.mean, 10.5);
  EXPECT_EQ(s.p95, 19.0);  // index ceil(0.95 * 20) - 1 = 18 of 1..20
  EXPECT_EQ(s.max, 20.0);
  const SeriesSummary one = summarizeSeries({3.5});
  EXPECT_EQ(one.p95, 3.5);
  const SeriesSummary empty = summarizeSeries({});
  EXPECT_EQ(empty.count, 0u);
  EXPECT_EQ(empty.mean, 0.0);
  EXPECT_THROW(summarizeSeries({1.0, std::nan("")}), std::invalid_argument);
}

}  // namespace
}  // namespace testbed
