// Error metrics on hand-made images whose answers are known by construction.
#include "testbed/metrics/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace testbed {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

ImageF makeImage(int w, int h, const std::function<float(int, int)>& value) {
  ImageF image{w, h, 1, {}};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.pixels.push_back(value(x, y));
  return image;
}

ImageF pad(const ImageF& image, int border, float value) {
  return makeImage(image.width + 2 * border, image.height + 2 * border, [&](int x, int y) {
    const int ix = x - border, iy = y - border;
    if (ix < 0 || iy < 0 || ix >= image.width || iy >= image.height) return value;
    return image.at(ix, iy);
  });
}

bool inSquare(int x, int y, int lo, int hi) { return x >= lo && x < hi && y >= lo && y < hi; }

// 60x60, ground-truth shadow square [10,50)^2. Its far-from-boundary part (distance to the
// inner boundary ring > 8) is [19,40]^2 = 22^2 = 484 pixels; the centre [25,35)^2 (100
// pixels) lies inside it.
ImageF squareShadowGt() { return makeImage(60, 60, [](int x, int y) { return inSquare(x, y, 10, 50) ? 0.f : 1.f; }); }
ImageF squareShadowWithLitCentre(float centre = 1.f) {
  return makeImage(60, 60, [=](int x, int y) {
    return inSquare(x, y, 25, 35) ? centre : inSquare(x, y, 10, 50) ? 0.f : 1.f;
  });
}

void expectSame(const ErrorMetrics& a, const ErrorMetrics& b) {
  EXPECT_DOUBLE_EQ(a.mismatchPct, b.mismatchPct);
  EXPECT_DOUBLE_EQ(a.edgeMismatchPct, b.edgeMismatchPct);
  EXPECT_DOUBLE_EQ(a.rmse, b.rmse);
  EXPECT_DOUBLE_EQ(a.leakPct, b.leakPct);
  EXPECT_DOUBLE_EQ(a.overestimationPct, b.overestimationPct);
  EXPECT_DOUBLE_EQ(a.boundaryMean, b.boundaryMean);
  EXPECT_DOUBLE_EQ(a.boundaryP95, b.boundaryP95);
  EXPECT_EQ(a.softRmse.has_value(), b.softRmse.has_value());
  if (a.softRmse && b.softRmse) {
    EXPECT_DOUBLE_EQ(*a.softRmse, *b.softRmse);
  }
  EXPECT_EQ(a.receivers, b.receivers);
  EXPECT_EQ(a.gtBoundaryPixels, b.gtBoundaryPixels);
}

TEST(Metrics, IdenticalImagesGiveZeros) {
  const ImageF gt = makeImage(40, 30, [](int x, int y) { return (x - 20) * (x - 20) + (y - 15) * (y - 15) < 64 ? 0.f : 1.f; });
  const ErrorMetrics m = computeErrorMetrics(gt, gt);
  ErrorMetrics zero;  // every error 0, no soft reference
  zero.receivers = 40 * 30;
  zero.gtBoundaryPixels = m.gtBoundaryPixels;
  expectSame(m, zero);
  EXPECT_GT(m.gtBoundaryPixels, 0);
}

TEST(Metrics, ShiftedHalfPlaneEdge) {
  // GT lit for x < 20: boundary pixels are columns 19 and 20. Technique lit for x < 23:
  // boundary columns 22 and 23. Per row the pooled distances are 22->20: 2, 23->20: 3,
  // 19->22: 3, 20->22: 2, so mean 2.5 and p95 3 (index 37 of 20 twos and 20 threes).
  const ImageF gt = makeImage(40, 10, [](int x, int) { return x < 20 ? 1.f : 0.f; });
  const ImageF v = makeImage(40, 10, [](int x, int) { return x < 23 ? 1.f : 0.f; });
  const ErrorMetrics m = computeErrorMetrics(v, gt);
  EXPECT_EQ(m.gtBoundaryPixels, 20);
  EXPECT_DOUBLE_EQ(m.mismatchPct, 100.0 * 30 / 400);  // columns 20..22
  // Band: columns within 3 of 19 or 20 are 16..23 (80 pixels), 30 of them wrong.
  EXPECT_DOUBLE_EQ(m.edgeMismatchPct, 100.0 * 30 / 80);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(30.0 / 400));
  EXPECT_DOUBLE_EQ(m.boundaryMean, 2.5);
  EXPECT_DOUBLE_EQ(m.boundaryP95, 3.0);
  EXPECT_EQ(m.leakPct, 0);  // the wrong strip is within the 8 px margin
  EXPECT_EQ(m.overestimationPct, 0);

  // One-pixel shift: distances 0, 1, 1, 0 per row.
  const ErrorMetrics one = computeErrorMetrics(makeImage(40, 10, [](int x, int) { return x < 21 ? 1.f : 0.f; }), gt);
  EXPECT_DOUBLE_EQ(one.boundaryMean, 0.5);
  EXPECT_DOUBLE_EQ(one.boundaryP95, 1.0);
  EXPECT_DOUBLE_EQ(one.mismatchPct, 100.0 * 10 / 400);
}

TEST(Metrics, HorizontalEdgeGivesTheSameAsVertical) {
  const ImageF gt = makeImage(10, 40, [](int, int y) { return y < 20 ? 1.f : 0.f; });
  const ImageF v = makeImage(10, 40, [](int, int y) { return y < 23 ? 1.f : 0.f; });
  const ErrorMetrics m = computeErrorMetrics(v, gt);
  EXPECT_DOUBLE_EQ(m.mismatchPct, 7.5);
  EXPECT_DOUBLE_EQ(m.edgeMismatchPct, 37.5);
  EXPECT_DOUBLE_EQ(m.boundaryMean, 2.5);
  EXPECT_DOUBLE_EQ(m.boundaryP95, 3.0);
}

TEST(Metrics, BoundaryP95IsNearestRank) {
  // 40x3, edge at column 20 in both; the technique adds a lit pair at (30,1),(31,1) in
  // the shadow. Pool (n = 20): 12 zeros from the shared edge, then the pair's 8 boundary
  // pixels at their column minus 20: 9, 10, 10, 10, 11, 11, 11, 12. Nearest rank
  // ceil(0.95 * 20) - 1 = 18 picks 11, not the maximum 12.
  const ImageF gt = makeImage(40, 3, [](int x, int) { return x < 20 ? 1.f : 0.f; });
  const ImageF v = makeImage(40, 3, [](int x, int y) { return x < 20 || (y == 1 && (x == 30 || x == 31)) ? 1.f : 0.f; });
  const ErrorMetrics m = computeErrorMetrics(v, gt);
  EXPECT_DOUBLE_EQ(m.boundaryP95, 11.0);
  EXPECT_DOUBLE_EQ(m.boundaryMean, 84.0 / 20);
  EXPECT_DOUBLE_EQ(m.mismatchPct, 100.0 * 2 / 120);
}

TEST(Metrics, LeakIsShareOfFarShadowPixels) {
  const ErrorMetrics m = computeErrorMetrics(squareShadowWithLitCentre(), squareShadowGt());
  EXPECT_DOUBLE_EQ(m.leakPct, 100.0 * 100 / 484);
  EXPECT_EQ(m.overestimationPct, 0);
  EXPECT_DOUBLE_EQ(m.mismatchPct, 100.0 * 100 / 3600);
  EXPECT_EQ(m.edgeMismatchPct, 0);  // the centre is 15 px from the boundary
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(100.0 / 3600));
}

TEST(Metrics, OverestimationIsShareOfFarLitPixels) {
  const ImageF gt = makeImage(60, 60, [](int x, int y) { return inSquare(x, y, 10, 50) ? 1.f : 0.f; });
  const ImageF v = makeImage(60, 60, [](int x, int y) {
    return inSquare(x, y, 25, 35) ? 0.f : inSquare(x, y, 10, 50) ? 1.f : 0.f;
  });
  const ErrorMetrics m = computeErrorMetrics(v, gt);
  EXPECT_DOUBLE_EQ(m.overestimationPct, 100.0 * 100 / 484);
  EXPECT_EQ(m.leakPct, 0);
  EXPECT_DOUBLE_EQ(m.mismatchPct, 100.0 * 100 / 3600);
}

TEST(Metrics, LeakThresholdIsStrictButMismatchIsNot) {
  // v = 0.5 counts as lit for mismatch (>= 0.5) but not as a leak (> 0.5).
  const ErrorMetrics m = computeErrorMetrics(squareShadowWithLitCentre(0.5f), squareShadowGt());
  EXPECT_DOUBLE_EQ(m.mismatchPct, 100.0 * 100 / 3600);
  EXPECT_EQ(m.leakPct, 0);
}

TEST(Metrics, PixelsWithinMarginDoNotCount) {
  // A wrong strip at columns 12..14 inside the shadow square: 2..4 px from the boundary.
  const ImageF v = makeImage(60, 60, [](int x, int y) {
    if (x >= 12 && x <= 14 && y >= 20 && y < 40) return 1.f;
    return inSquare(x, y, 10, 50) ? 0.f : 1.f;
  });
  const ErrorMetrics m = computeErrorMetrics(v, squareShadowGt());
  EXPECT_DOUBLE_EQ(m.mismatchPct, 100.0 * 60 / 3600);
  EXPECT_EQ(m.leakPct, 0);
  // With a 1 px margin the far shadow region is [12,47]^2 = 1296 pixels and the strip counts.
  const ErrorMetrics tight = computeErrorMetrics(v, squareShadowGt(), nullptr, MetricOptions{1, 3});
  EXPECT_DOUBLE_EQ(tight.leakPct, 100.0 * 60 / 1296);
}

TEST(Metrics, NaNBackgroundIsIgnored) {
  const ImageF gt = squareShadowGt(), v = squareShadowWithLitCentre();
  const ImageF reference = makeImage(60, 60, [](int, int) { return 0.5f; });
  const ErrorMetrics plain = computeErrorMetrics(v, gt, &reference);
  // The technique's value outside the receivers does not matter, NaN or not.
  for (float outside : {kNaN, 0.7f}) {
    const ImageF refPadded = pad(reference, 5, kNaN);
    const ErrorMetrics padded = computeErrorMetrics(pad(v, 5, outside), pad(gt, 5, kNaN), &refPadded);
    expectSame(plain, padded);
  }
}

TEST(Metrics, SoftRmseOnlyWithReference) {
  const ImageF gt = squareShadowGt();
  EXPECT_FALSE(computeErrorMetrics(gt, gt).softRmse.has_value());
  const ImageF reference = makeImage(60, 60, [](int, int) { return 0.5f; });
  const ErrorMetrics m = computeErrorMetrics(gt, gt, &reference);
  ASSERT_TRUE(m.softRmse.has_value());
  EXPECT_DOUBLE_EQ(*m.softRmse, 0.5);  // binary values, every one 0.5 away
  EXPECT_EQ(m.rmse, 0);
}

// A 10x1 reference: umbra (0) at x 0-2, penumbra ramp 0.25, 0.5, 0.75 at x 3-5, lit (1) at
// x 6-9; the edges of the region (eps itself, 1 - eps) fall outside the penumbra.
ImageF softReference() {
  const float values[10] = {0, 0, float(kPenumbraEpsilon), 0.25f, 0.5f, 0.75f, float(1 - kPenumbraEpsilon), 1, 1, 1};
  return makeImage(10, 1, [&](int x, int) { return values[x]; });
}

TEST(SoftMetrics, PenumbraAndOutsideErrorsSplitByTheReferencesRegion) {
  const ImageF reference = softReference();
  // Hard shadow at x < 5: in the penumbra |0-0.25| + |0-0.5| + |1-0.75| = 1 over 3 pixels;
  // outside: x 0-1 exact, x 2 off by eps, x 6 by eps, x 7-9 exact: 2 eps over 7 pixels.
  const ImageF hard = makeImage(10, 1, [](int x, int) { return x < 5 ? 0.f : 1.f; });
  const ErrorMetrics m = computeErrorMetrics(hard, hard, &reference);
  ASSERT_TRUE(m.softPenumbraMae && m.softOutsideMae && m.softUmbraLeak);
  EXPECT_NEAR(*m.softPenumbraMae, 1.0 / 3.0, 1e-7);
  EXPECT_NEAR(*m.softOutsideMae, 2 * kPenumbraEpsilon / 7, 1e-7);
  EXPECT_DOUBLE_EQ(*m.softUmbraLeak, 0.0);  // every umbra pixel (x 0-2) reads 0
  // RMSE over all 10: (0.25² + 0.5² + 0.25² + 2 eps²) / 10.
  const double eps2 = kPenumbraEpsilon * kPenumbraEpsilon;
  EXPECT_NEAR(*m.softRmse, std::sqrt((0.0625 + 0.25 + 0.0625 + 2 * eps2) / 10), 1e-7);
}

TEST(SoftMetrics, UmbraLeakIsTheMeanVisibilityInTheReferencesUmbra) {
  const ImageF reference = softReference();
  // Light bleeding: 0.3 everywhere the reference is in umbra (x 0-2), exact elsewhere.
  const ImageF bleeding = makeImage(10, 1, [&](int x, int) { return x < 3 ? 0.3f : reference.at(x, 0); });
  const ErrorMetrics m = computeErrorMetrics(bleeding, reference, &reference);
  EXPECT_NEAR(*m.softUmbraLeak, 0.3, 1e-7);
  EXPECT_DOUBLE_EQ(*m.softPenumbraMae, 0.0);
  EXPECT_NEAR(*m.softOutsideMae, (0.3 + 0.3 + (0.3 - kPenumbraEpsilon)) / 7, 1e-7);
}

TEST(SoftMetrics, AReferenceWithoutPenumbraOrUmbraGivesZeros) {
  const ImageF lit = makeImage(4, 4, [](int, int) { return 1.f; });
  const ImageF dark = makeImage(4, 4, [](int, int) { return 0.f; });
  const ErrorMetrics m = computeErrorMetrics(dark, lit, &lit);
  EXPECT_DOUBLE_EQ(*m.softPenumbraMae, 0.0);  // no penumbra: empty region
  EXPECT_DOUBLE_EQ(*m.softUmbraLeak, 0.0);    // no umbra
  EXPECT_DOUBLE_EQ(*m.softOutsideMae, 1.0);
  EXPECT_FALSE(computeErrorMetrics(dark, lit).softPenumbraMae.has_value());  // no reference, no soft metric
}

TEST(SoftMetrics, SoftHeatMapBlendsTheReferencesGreyTowardTheErrorsSign) {
  const ImageF reference = makeImage(3, 1, [](int x, int) { return x == 0 ? kNaN : 0.5f; });
  const ImageF v = makeImage(3, 1, [](int x, int) { return x == 1 ? 0.5f : 1.0f; });
  const ImageF map = softErrorHeatMap(v, reference);
  for (int k = 0; k < 3; ++k) {
    EXPECT_FLOAT_EQ(map.at(0, 0, k), kHeatBackground[k]);
    const float grey = 0.5f * kHeatShadow[k] + 0.5f * kHeatLit[k];
    EXPECT_FLOAT_EQ(map.at(1, 0, k), grey);                                  // exact: plain grey
    EXPECT_FLOAT_EQ(map.at(2, 0, k), 0.5f * grey + 0.5f * kHeatFalseLit[k]);  // 0.5 too lit: half red
  }
}

TEST(Metrics, BadInputsThrow) {
  const ImageF gt = makeImage(8, 6, [](int x, int) { return x < 4 ? 1.f : 0.f; });
  EXPECT_THROW(computeErrorMetrics(makeImage(8, 7, [](int, int) { return 1.f; }), gt), std::invalid_argument);
  const ImageF badRef = makeImage(6, 8, [](int, int) { return 1.f; });
  EXPECT_THROW(computeErrorMetrics(gt, gt, &badRef), std::invalid_argument);
  ImageF rgb{8, 6, 3, std::vector<float>(8 * 6 * 3, 1.f)};
  EXPECT_THROW(computeErrorMetrics(rgb, gt), std::invalid_argument);
  EXPECT_THROW(errorHeatMap(makeImage(7, 6, [](int, int) { return 1.f; }), gt), std::invalid_argument);

  ImageF lost = gt;
  lost.pixels[2 * 8 + 3] = kNaN;  // pixel (3, 2)
  try {
    computeErrorMetrics(lost, gt);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("(3, 2)"), std::string::npos) << e.what();
  }
  const ImageF empty = makeImage(8, 6, [](int, int) { return kNaN; });
  EXPECT_THROW(computeErrorMetrics(empty, empty), std::invalid_argument);
}

TEST(Metrics, OneSideWithoutBoundaryGivesDiagonal) {
  // 30x40: diagonal 50.
  const ImageF lit = makeImage(30, 40, [](int, int) { return 1.f; });
  const ImageF square = makeImage(30, 40, [](int x, int y) { return inSquare(x, y, 5, 25) ? 0.f : 1.f; });
  for (const auto& [v, gt] : {std::pair{&square, &lit}, std::pair{&lit, &square}}) {
    const ErrorMetrics m = computeErrorMetrics(*v, *gt);
    EXPECT_DOUBLE_EQ(m.boundaryMean, 50.0);
    EXPECT_DOUBLE_EQ(m.boundaryP95, 50.0);
  }
  // Neither has a boundary: 0, and with no GT boundary every receiver is "far".
  const ImageF dark = makeImage(30, 40, [](int, int) { return 0.f; });
  const ErrorMetrics m = computeErrorMetrics(dark, lit);
  EXPECT_EQ(m.boundaryMean, 0);
  EXPECT_EQ(m.boundaryP95, 0);
  EXPECT_EQ(m.gtBoundaryPixels, 0);
  EXPECT_DOUBLE_EQ(m.mismatchPct, 100.0);
  EXPECT_DOUBLE_EQ(m.overestimationPct, 100.0);
  EXPECT_EQ(m.edgeMismatchPct, 0);
}

TEST(Metrics, HeatMapColoursEachClass) {
  // Row 0: background, agreeing lit, agreeing shadow, filtered shadow (gt 0, v 0.25).
  // Row 1: false lit, false shadow, filtered lit (gt 1, v 0.75), background with NaN v.
  const float gtValues[] = {kNaN, 1, 0, 0, 0, 1, 1, kNaN};
  const float vValues[] = {1, 1, 0, 0.25f, 1, 0.2f, 0.75f, kNaN};
  ImageF gt{4, 2, 1, {std::begin(gtValues), std::end(gtValues)}};
  ImageF v{4, 2, 1, {std::begin(vValues), std::end(vValues)}};
  const ImageF heat = errorHeatMap(v, gt);
  ASSERT_EQ(heat.width, 4);
  ASSERT_EQ(heat.height, 2);
  ASSERT_EQ(heat.channels, 3);
  auto expectColour = [&](int x, int y, std::array<float, 3> c) {
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(heat.at(x, y, k), c[k]) << x << "," << y << " channel " << k;
  };
  auto mix = [](std::array<float, 3> a, std::array<float, 3> b, float t) {
    return std::array<float, 3>{(1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1], (1 - t) * a[2] + t * b[2]};
  };
  expectColour(0, 0, kHeatBackground);
  expectColour(1, 0, kHeatLit);
  expectColour(2, 0, kHeatShadow);
  expectColour(3, 0, mix(kHeatShadow, kHeatFalseLit, 0.25f));
  expectColour(0, 1, kHeatFalseLit);
  expectColour(1, 1, kHeatFalseShadow);
  expectColour(2, 1, mix(kHeatLit, kHeatFalseShadow, 0.25f));
  expectColour(3, 1, kHeatBackground);
  // The classes are told apart.
  EXPECT_NE(kHeatBackground, kHeatShadow);
  EXPECT_NE(kHeatShadow, kHeatLit);
}

}  // namespace
}  // namespace testbed

namespace testbed {
namespace {

// Each percentage's denominator on a half-plane whose answers are counted by hand: shadow
// x < 30 on 60 × 60; boundary pixels in columns 29 and 30; "far" beyond 8 px: columns
// 0-20 and 39-59; the 3 px band: columns 26-33.
TEST(MetricsDenominators, HalfPlaneCountsAndFlags) {
  const ImageF gt = makeImage(60, 60, [](int x, int) { return x < 30 ? 0.f : 1.f; });
  const ErrorMetrics m = computeErrorMetrics(gt, gt);
  EXPECT_EQ(m.receivers, 3600);
  EXPECT_EQ(m.gtShadowReceivers, 1800);
  EXPECT_EQ(m.gtLitReceivers, 1800);
  EXPECT_EQ(m.gtBoundaryPixels, 120);
  EXPECT_EQ(m.farShadowReceivers, 21 * 60);
  EXPECT_EQ(m.farLitReceivers, 21 * 60);
  EXPECT_EQ(m.edgeBandPixels, 8 * 60);
  EXPECT_FALSE(groundTruthFlag(m).has_value());

  const ImageF lit = makeImage(10, 10, [](int, int) { return 1.f; });
  EXPECT_STREQ(*groundTruthFlag(computeErrorMetrics(lit, lit)), "entirely lit from the camera");
  const ImageF unlit = makeImage(10, 10, [](int, int) { return 0.f; });
  EXPECT_STREQ(*groundTruthFlag(computeErrorMetrics(unlit, unlit)), "entirely unlit from the camera");
  // Lit and shadowed receivers apart, a column of background between them: no boundary.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const ImageF apart = makeImage(10, 10, [&](int x, int) { return x < 4 ? 0.f : x == 4 ? nan : 1.f; });
  EXPECT_STREQ(*groundTruthFlag(computeErrorMetrics(apart, apart)), "no shadow boundary");
  EXPECT_FALSE(groundTruthFlag(ErrorMetrics{}).has_value());  // not counted: no flag
}

}  // namespace
}  // namespace testbed
