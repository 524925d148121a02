// Temporal metrics on hand-made sequences whose answers are known by construction.
#include "testbed/metrics/temporal_metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
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
  EXPECT_EQ(m.series[1].stablePairs, 15u);
  EXPECT_EQ(m.series[1].flicker, 0.0);
  EXPECT_EQ(m.series[1].crawlPct, 0.0);
  EXPECT_EQ(m.stablePairs, 30u);
  EXPECT_EQ(m.framePairs, 2);
  EXPECT_NEAR(m.flicker, 2.2 / 30, 1e-6);
  EXPECT_NEAR(m.crawlPct, 100.0 / 30, 1e-12);
  EXPECT_NEAR(m.crawlMissedPct, 100.0 / 30, 1e-12);
}

// A camera looking straight down on the floor z = 0, orthographic, 4x2 pixels of side s,
// centred at x = k s in frame k: it pans one pixel to the right per frame, so pixel x of
// frame 1 sees what pixel x + 1 of frame 0 saw.
constexpr int kW = 4, kH = 2;
glm::mat4 panViewProjection(int k, float s) {
  const float cx = float(k) * s;
  const glm::mat4 view = glm::lookAt(glm::vec3(cx, 0, 100 * s), glm::vec3(cx, 0, 0), glm::vec3(0, 1, 0));
  return glm::ortho(-2 * s, 2 * s, -s, s, 0.1f * s, 200 * s) * view;
}
// World x of pixel column x in frame k: (x + k - 1.5) s; row y sees world y = (0.5 - y) s.
float panWorldX(int x, int k, float s) { return (float(x + k) - 1.5f) * s; }
ImageF panPositions(int k, float s, const std::map<std::pair<int, int>, float>& raised = {}) {
  ImageF image{kW, kH, 4, {}};
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const auto it = raised.find({x, y});
      const float z = it == raised.end() ? 0.f : it->second * s;
      image.pixels.insert(image.pixels.end(), {panWorldX(x, k, s), (0.5f - float(y)) * s, z, 1.f});
    }
  return image;
}
// The ground truth's shadow is fixed on the floor: world x < 0 is in shadow.
ImageF panGroundTruth(int k) { return makeImage(kW, kH, [k](int x, int) { return panWorldX(x, k, 1) < 0 ? 0.f : 1.f; }); }

TEST(TemporalMetrics, MovingCameraMatchesReprojectedAndDropsDisoccluded) {
  // Frame 0's pixel (1,1) saw an occluder 5 pixel footprints above the floor, gone in frame 1:
  // frame 1's pixel (0,1) sees the floor point under it (a disocclusion). G0 there is lit
  // (the occluder's top) and V0 wrongly dark, so counting that pair would add flicker 1.
  ImageF g0 = panGroundTruth(0), g1 = panGroundTruth(1);
  g0.pixels[1 * kW + 1] = 1.f;
  ImageF v0 = g0, v1 = g1;
  v0.pixels[1 * kW + 1] = 0.f;
  // A wrong value stuck to the floor point world x = 1.5: pixel 3 in frame 0, pixel 2 in
  // frame 1. Reprojected, it is the same error on the same point: no flicker.
  v0.pixels[0 * kW + 3] = 0.2f;
  v1.pixels[0 * kW + 2] = 0.2f;
  // A new error in frame 1 at (1,1) (world x = 0.5, lit): dv = -0.6, and V turns dark: crawl.
  v1.pixels[1 * kW + 1] = 0.4f;
  const ImageF p0 = panPositions(0, 1, {{{1, 1}, 5.f}}), p1 = panPositions(1, 1);

  TemporalAccumulator accumulator;
  EXPECT_FALSE(accumulator.addFrame({.frame = 0, .visibility = v0, .groundTruth = g0, .positions = p0,
                                     .viewProjection = panViewProjection(0, 1)}));
  const auto pair = accumulator.addFrame(
      {.frame = 1, .visibility = v1, .groundTruth = g1, .positions = p1, .viewProjection = panViewProjection(1, 1)});
  ASSERT_TRUE(pair);
  // Frame 1's column 3 reprojects off-screen, (0,1) is disoccluded: 8 - 2 - 1 = 5 pairs.
  EXPECT_EQ(pair->stablePairs, 5u);
  EXPECT_NEAR(pair->flicker, 0.6 / 5, 1e-6);
  EXPECT_NEAR(pair->crawlPct, 20.0, 1e-12);
  EXPECT_EQ(pair->crawlMissedPct, 0.0);

  // The ground truth against itself under the moving camera reads 0.
  TemporalAccumulator self;
  self.addFrame({.frame = 0, .visibility = g0, .groundTruth = g0, .positions = p0, .viewProjection = panViewProjection(0, 1)});
  self.addFrame({.frame = 1, .visibility = g1, .groundTruth = g1, .positions = p1, .viewProjection = panViewProjection(1, 1)});
  expectZero(self.result());
  EXPECT_EQ(self.result().stablePairs, 5u);
}

TEST(TemporalMetrics, ToleranceIsInPixelFootprints) {
  // Frame 0's floor raised by 1.5 footprints at (2,0) (kept: within 2) and 2.5 at (2,1)
  // (dropped), at three scales: the same pixels pass whatever the scene's units.
  for (const float s : {0.01f, 1.f, 40.f}) {
    SCOPED_TRACE(s);
    const ImageF g0 = panGroundTruth(0), g1 = panGroundTruth(1);
    TemporalAccumulator accumulator;
    accumulator.addFrame({.frame = 0, .visibility = g0, .groundTruth = g0,
                          .positions = panPositions(0, s, {{{2, 0}, 1.5f}, {{2, 1}, 2.5f}}),
                          .viewProjection = panViewProjection(0, s)});
    const auto pair = accumulator.addFrame({.frame = 1, .visibility = g1, .groundTruth = g1,
                                            .positions = panPositions(1, s), .viewProjection = panViewProjection(1, s)});
    ASSERT_TRUE(pair);
    EXPECT_EQ(pair->stablePairs, 5u);  // 6 on screen, (1,1) -> (2,1) dropped
  }
}

// A perspective camera (90 degrees, 32x32) at height h looking straight down, panning one
// pixel footprint f = h / 16 of the floor per frame. Frame 0's pixel (20,10) saw an occluder
// at h / 2 (8 footprints above the floor: dropped), its pixel (5,5) a bump at 0.05 h (under
// one and a half footprints along the ray: kept). The footprint follows the depth, so the
// same pixels pass at h = 1 and h = 100.
TEST(TemporalMetrics, PerspectiveFootprintFollowsDepth) {
  constexpr int n = 32;
  for (const float h : {1.f, 100.f}) {
    SCOPED_TRACE(h);
    const float f = h / 16;
    auto viewProjection = [&](int k) {
      const glm::vec3 eye(float(k) * f, 0, h);
      return glm::perspective(glm::radians(90.f), 1.f, 0.01f * h, 10 * h) *
             glm::lookAt(eye, eye - glm::vec3(0, 0, h), glm::vec3(0, 1, 0));
    };
    auto positions = [&](int k, const std::map<std::pair<int, int>, float>& raised) {
      ImageF image{n, n, 4, {}};
      const glm::vec3 eye(float(k) * f, 0, h);
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
          const glm::vec3 floor = eye + h * glm::vec3((float(x) + 0.5f) / n * 2 - 1, 1 - (float(y) + 0.5f) / n * 2, -1);
          const auto it = raised.find({x, y});
          const glm::vec3 p = it == raised.end() ? floor : eye + (1 - it->second) * (floor - eye);
          image.pixels.insert(image.pixels.end(), {p.x, p.y, p.z, 1.f});
        }
      return image;
    };
    const ImageF lit = makeImage(n, n, [](int, int) { return 1.f; });
    TemporalAccumulator accumulator;
    accumulator.addFrame({.frame = 0, .visibility = lit, .groundTruth = lit,
                          .positions = positions(0, {{{20, 10}, 0.5f}, {{5, 5}, 0.05f}}),
                          .viewProjection = viewProjection(0)});
    const auto pair = accumulator.addFrame({.frame = 1, .visibility = lit, .groundTruth = lit,
                                            .positions = positions(1, {}), .viewProjection = viewProjection(1)});
    ASSERT_TRUE(pair);
    EXPECT_EQ(pair->stablePairs, std::size_t((n - 1) * n - 1));  // last column off screen, (19,10) disoccluded
  }
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
  EXPECT_THROW(TemporalAccumulator({.toleranceFootprints = 0}), std::invalid_argument);
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
