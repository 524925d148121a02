// Tests of `pcf`: kernel 1 is plain shadow mapping (bit for bit on llvmpipe); against the
// ground truth larger kernels add no leak and bilinear taps pull the contour closer; the box filter's
// values are counts of lit taps over k²; bad kernels are rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

#include "testbed/harness/frame_runner.h"
#include "testbed/core/error.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

using test::bundledScene;
using test::runTechnique;

RenderSettings smallSettings(int shadowMapSize) { return test::renderSettings({640, 360}, shadowMapSize); }

class PcfImage : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

// Same texel, same test: with one tap PCF must be sm, NaN background included — bit for bit
// on llvmpipe; two programs, so elsewhere within test::expectSameVisibilityAcrossPrograms.
TEST_F(PcfImage, KernelOneEqualsShadowMapping) {
  for (const std::string name : {"wall", "fence"}) {
    SCOPED_TRACE(name);
    const Scene scene = bundledScene(name);
    FrameRunner runner(scene, smallSettings(1024));
    const ImageF sm = runTechnique(runner, "sm").visibility;
    const ImageF pcf = runTechnique(runner, "pcf", {{"kernel", "1"}}).visibility;
    test::expectSameVisibilityAcrossPrograms(sm, pcf, [&] { return test::groundTruthVisibility(runner); });
    EXPECT_GT(test::receiversOf(sm).count, 10000);
  }
}

// What pcf with a k×k kernel gives on one frame, counted: background pixels that are not
// NaN; receivers that are NaN, outside [0, 1], off the box filter's grid (a whole number
// of lit taps over k²), or strictly between 0 and 1.
struct PcfValues {
  int notNanBackground = 0, nanOnReceiver = 0, outOfRange = 0, offGrid = 0, partial = 0;
};

PcfValues pcfValues(FrameRunner& runner, int k, bool bilinear) {
  const ImageF& positions = runner.positions();
  const ImageF v =
      runTechnique(runner, "pcf", {{"kernel", std::to_string(k)}, {"bilinear", bilinear ? "true" : "false"}}).visibility;
  PcfValues counts;
  for (int y = 0; y < v.height; ++y)
    for (int x = 0; x < v.width; ++x) {
      const float value = v.at(x, y);
      if (positions.at(x, y, 3) <= 0.5f) {
        counts.notNanBackground += !std::isnan(value);
        continue;
      }
      if (std::isnan(value)) {
        ++counts.nanOnReceiver;
        continue;
      }
      counts.outOfRange += value < 0.0f || value > 1.0f;
      const float taps = value * float(k * k);
      counts.offGrid += std::abs(taps - std::round(taps)) > 1e-3f;
      counts.partial += value > 0.0f && value < 1.0f;
    }
  return counts;
}

// Values are in [0, 1] and defined on every receiver. The box filter's are a whole number
// of lit taps over k², some strictly between 0 and 1 (it does filter); bilinear taps give
// continuous values, off that grid. 31 is the widest kernel (the EDTSM* paper's 31²).
TEST_F(PcfImage, ValuesAreInTheUnitIntervalAndTheBoxFilterCountsLitTaps) {
  const Scene scene = bundledScene("wall");
  FrameRunner runner(scene, smallSettings(512));
  for (const auto& [k, bilinear] : {std::pair{3, false}, std::pair{5, false}, std::pair{31, false}, std::pair{1, true}, std::pair{3, true}}) {
    SCOPED_TRACE("kernel " + std::to_string(k) + (bilinear ? " bilinear" : " box"));
    const PcfValues values = pcfValues(runner, k, bilinear);
    EXPECT_EQ(values.nanOnReceiver, 0);
    EXPECT_EQ(values.outOfRange, 0);
    if (bilinear) {
      EXPECT_GT(values.offGrid, 100);  // the bilinear weights leave the box filter's grid
      continue;
    }
    EXPECT_EQ(values.notNanBackground, 0);
    EXPECT_EQ(values.offGrid, 0);
    EXPECT_GT(values.partial, 100);
  }
}

// Against shadow volumes at a fine map (2048²) on every bundled scene, 640×360. Asserted:
// - leak_pct of the box filter with k = 3, 5, 7 is <= kernel 1's (= sm's): PCF filters
//   test results, so it adds no leak of its own.
// - bilinear PCF 3×3 has boundary_px.mean <= kernel 1's: its contour interpolates between
//   texels, which is what the option is for.
// Printed, not asserted: the box filter's boundary_px.mean against kernel 1's. It is not
// monotonic in k (marked "> k=1" below): the box is centred on the receiver's texel, so
// its value is constant across each texel and its 0.5 contour is the same texel staircase
// as sm's; widening it only rounds corners and thins narrow shadows, by a few pixels.
void checkAgainstGroundTruth(const std::string& name) {
  test::sharedContext();
  std::cout << "scene       variant       mismatch%   edge%  boundary_mean  boundary_p95   leak%    rmse\n";
  const Scene scene = bundledScene(name);
  FrameRunner runner(scene, smallSettings(2048));
  const ImageF truth = test::groundTruthVisibility(runner);
  auto measure = [&](int k, bool bilinear, const ErrorMetrics* baseline) {
    const ErrorMetrics m = computeErrorMetrics(
        runTechnique(runner, "pcf", {{"kernel", std::to_string(k)}, {"bilinear", bilinear ? "true" : "false"}})
            .visibility,
        truth);
    const std::string label = "k=" + std::to_string(k) + (bilinear ? " bilinear" : "");
    char line[200];
    std::snprintf(line, sizeof line, "%-11s %-12s %9.4f  %6.3f  %13.4f  %12.3f  %6.3f  %.4f%s\n", name.c_str(),
                  label.c_str(), m.mismatchPct, m.edgeMismatchPct, m.boundaryMean, m.boundaryP95, m.leakPct,
                  m.rmse, baseline && m.boundaryMean > baseline->boundaryMean ? "  (boundary > k=1)" : "");
    std::cout << line;
    return m;
  };
  const ErrorMetrics one = measure(1, false, nullptr);
  for (const int k : {3, 5, 7}) {
    SCOPED_TRACE("kernel " + std::to_string(k));
    EXPECT_LE(measure(k, false, &one).leakPct, one.leakPct);
  }
  measure(1, true, &one);
  EXPECT_LE(measure(3, true, &one).boundaryMean, one.boundaryMean) << "bilinear 3x3";
}

// One test per scene keeps each well under a second on llvmpipe.
TEST(PcfGroundTruth, Wall) { checkAgainstGroundTruth("wall"); }
TEST(PcfGroundTruth, Fence) { checkAgainstGroundTruth("fence"); }
TEST(PcfGroundTruth, Bunny) { checkAgainstGroundTruth("bunny"); }
TEST(PcfGroundTruth, DragonSun) { checkAgainstGroundTruth("dragon_sun"); }

TEST(PcfParameters, RejectsEvenAndOutOfRangeKernels) {
  const auto& specs = findTechnique("pcf").info->parameters;
  for (const char* kernel : {"4", "33", "0", "-1", "2.5"})
    EXPECT_THROW(resolveParameters("pcf", specs, {{"kernel", kernel}}), InputError) << "kernel=" << kernel;
  EXPECT_THROW(resolveParameters("pcf", specs, {{"bias", "2"}}), InputError);
  const ParameterSet defaults = resolveParameters("pcf", specs, {});
  EXPECT_EQ(defaults.getInt("kernel"), 3);
  EXPECT_FALSE(defaults.getBool("bilinear"));
  EXPECT_EQ(defaults.getFloat("bias"), 0.0);
  // The widest: the EDTSM* paper's 31².
  EXPECT_EQ(resolveParameters("pcf", specs, {{"kernel", "31"}}).getInt("kernel"), 31);
}

TEST(PcfParameters, IsAFilteredTechniqueOfItsOwnFamily) {
  const TechniqueInfo& info = *findTechnique("pcf").info;
  EXPECT_EQ(info.family, "pcf");
  EXPECT_EQ(info.output, OutputKind::Filtered);
}

}  // namespace
}  // namespace testbed
