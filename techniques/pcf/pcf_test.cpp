// Tests of `pcf`: kernel 1 is plain shadow mapping bit for bit; against the ground truth
// larger kernels add no leak and bilinear taps pull the contour closer; the box filter's
// values are counts of lit taps over k²; bad kernels are rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/core/error.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

using Assignments = std::map<std::string, std::string>;

Scene bundledScene(const std::string& name) {
  return loadScene(std::string(TESTBED_SOURCE_DIR) + "/scenes/" + name + ".json");
}

TechniqueRun runTechnique(FrameRunner& runner, const std::string& id, const Assignments& set = {}) {
  const auto& technique = findTechnique(id);
  return runner.run(technique, resolveParameters(id, technique.info->parameters, set));
}

RenderSettings smallSettings(int shadowMapSize) {
  RenderSettings settings;
  settings.size = {640, 360};
  settings.shadowMapSize = shadowMapSize;
  return settings;
}

class PcfImage : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

// Same texel, same test: with one tap PCF must be sm, NaN background included.
TEST_F(PcfImage, KernelOneEqualsShadowMappingPixelForPixel) {
  for (const std::string name : {"wall", "fence"}) {
    SCOPED_TRACE(name);
    const Scene scene = bundledScene(name);
    FrameRunner runner(scene, smallSettings(1024));
    const ImageF sm = runTechnique(runner, "sm").visibility;
    const ImageF pcf = runTechnique(runner, "pcf", {{"kernel", "1"}}).visibility;
    ASSERT_EQ(sm.pixels.size(), pcf.pixels.size());
    int differing = 0, receivers = 0;
    for (std::size_t i = 0; i < sm.pixels.size(); ++i) {
      const float a = sm.pixels[i], b = pcf.pixels[i];
      receivers += !std::isnan(a);
      differing += !(a == b || (std::isnan(a) && std::isnan(b)));
    }
    EXPECT_EQ(differing, 0);
    EXPECT_GT(receivers, 10000);
  }
}

// Values are in [0, 1], defined on every receiver, and for the box filter a whole number
// of lit taps over k²; some are strictly between 0 and 1 (it does filter). 31 is the widest
// kernel (the EDTSM* paper's 31²).
TEST_F(PcfImage, BoxFilterValuesAreMultiplesOfOneOverKSquared) {
  const Scene scene = bundledScene("wall");
  FrameRunner runner(scene, smallSettings(512));
  const ImageF& positions = runner.positions();
  for (const int k : {3, 5, 31}) {
    SCOPED_TRACE("kernel " + std::to_string(k));
    const ImageF v = runTechnique(runner, "pcf", {{"kernel", std::to_string(k)}}).visibility;
    int partial = 0, offGrid = 0, outOfRange = 0, nanOnReceiver = 0;
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x) {
        const bool receiver = positions.at(x, y, 3) > 0.5f;
        const float value = v.at(x, y);
        if (!receiver) {
          EXPECT_TRUE(std::isnan(value)) << "background pixel " << x << "," << y;
          continue;
        }
        if (std::isnan(value)) {
          ++nanOnReceiver;
          continue;
        }
        outOfRange += value < 0.0f || value > 1.0f;
        const float taps = value * float(k * k);
        offGrid += std::abs(taps - std::round(taps)) > 1e-3f;
        partial += value > 0.0f && value < 1.0f;
      }
    EXPECT_EQ(nanOnReceiver, 0);
    EXPECT_EQ(outOfRange, 0);
    EXPECT_EQ(offGrid, 0);
    EXPECT_GT(partial, 100);
  }
}

// Bilinear taps give continuous values, still in [0, 1] and defined on every receiver.
TEST_F(PcfImage, BilinearValuesAreInTheUnitInterval) {
  const Scene scene = bundledScene("wall");
  FrameRunner runner(scene, smallSettings(512));
  const ImageF& positions = runner.positions();
  for (const int k : {1, 3}) {
    SCOPED_TRACE("kernel " + std::to_string(k));
    const ImageF v = runTechnique(runner, "pcf", {{"kernel", std::to_string(k)}, {"bilinear", "true"}}).visibility;
    int bad = 0, offGrid = 0;
    for (int y = 0; y < v.height; ++y)
      for (int x = 0; x < v.width; ++x) {
        if (positions.at(x, y, 3) <= 0.5f) continue;
        const float value = v.at(x, y);
        bad += !(value >= 0.0f && value <= 1.0f);  // NaN counts as bad
        const float taps = value * float(k * k);
        offGrid += std::abs(taps - std::round(taps)) > 1e-3f;
      }
    EXPECT_EQ(bad, 0);
    EXPECT_GT(offGrid, 100);  // the bilinear weights leave the box filter's grid
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
  const auto& truthTechnique = shadowVolumeGroundTruth();
  const ImageF truth =
      runner.run(truthTechnique, resolveParameters("groundtruth", truthTechnique.info->parameters, {})).visibility;
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
