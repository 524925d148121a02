// The technique suite built by two front-ends: Mesa's GLSL compiler and Khronos' glslang to
// SPIR-V loaded through ARB_gl_spirv (testbed/gl/spirv.h), on the bundled scenes. Every
// program of a run — G-buffer, shadow map, the technique's passes, the ground truth — takes
// the path of its runner. Hard visibility is the same arithmetic on the same inputs: on
// llvmpipe it is identical, and elsewhere the GL specification does not promise that of two
// programs, so it is held to test::expectSameVisibilityAcrossPrograms's bounds there; filtered
// visibility may differ by how each front-end orders and contracts floating-point
// operations, within the bounds below (docs/portability.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testbed/gl/shader_path.h"
#include "testbed/harness/frame_runner.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

// Filtered visibility: how far the two front-ends may differ (docs/portability.md has the
// measured figures). A filter's sums, and its exponentials, contracted into fused
// multiply-adds by one front-end and not the other, differ by float ulps; Chebyshev's bound
// (vsm, evsm) divides by a variance that is a difference of near-equal moments, which
// amplifies them: measured at most 1.2e-3 (vsm), so 2e-3 for every filtered technique but
// one. The moment shadow map's Hamburger reconstruction (Peters & Klein, "Moment Shadow
// Mapping", I3D 2015, §3, Algorithm 2) solves a 3×3 system that is near-singular where one
// depth dominates the moments, and a few isolated pixels move by up to 0.3 (measured): for
// msm, the mean difference and the share of pixels off by more than 0.01 are bounded instead.
constexpr double kFilteredMaxDifference = 2e-3;
constexpr double kMomentMeanDifference = 1e-4, kMomentLargeShare = 1e-2, kLarge = 0.01;

struct Agreement {
  int receivers = 0;      // pixels that are a receiver on both paths
  int maskDiffers = 0;    // pixels a receiver on one path only
  int differing = 0;      // receivers whose visibility differs at all
  int sideDiffers = 0;    // receivers lit (>= 0.5) on one path and shadowed on the other
  int large = 0;          // receivers whose visibility differs by more than kLarge
  double maxAbs = 0, meanAbs = 0;
};

Agreement compare(const ImageF& glsl, const ImageF& spirv) {
  Agreement a;
  for (std::size_t i = 0; i < glsl.pixels.size(); ++i) {
    const float g = glsl.pixels[i], s = spirv.pixels[i];
    if (std::isnan(g) != std::isnan(s)) ++a.maskDiffers;
    if (std::isnan(g) || std::isnan(s)) continue;
    ++a.receivers;
    const double difference = std::abs(double(g) - double(s));
    a.differing += difference > 0;
    a.sideDiffers += (g < 0.5f) != (s < 0.5f);
    a.large += difference > kLarge;
    a.maxAbs = std::max(a.maxAbs, difference);
    a.meanAbs += difference;
  }
  if (a.receivers > 0) a.meanAbs /= a.receivers;
  return a;
}

struct Case {
  std::string scene;
  glm::ivec2 size;
  int mapSize;
  TechniquePath path;
  std::string label() const {
    return scene + "_" + std::to_string(size.x) + "x" + std::to_string(size.y) + "_" + std::string(pathName(path));
  }
  // What GoogleTest prints for the parameter (test listings and failures), rather than bytes.
  friend void PrintTo(const Case& c, std::ostream* out) { *out << c.label(); }
};

class SpirvPath : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override { test::sharedContext(); }

  // One line per technique, the figures docs/portability.md reports.
  static void report(const Case& c, const std::string& id, const Agreement& a) {
    std::printf("spirv-agreement %s %s: receivers %d, mask differs %d, differing %d, other side of 0.5 %d, "
                "over 0.01 %d, max %.3g, mean %.3g\n",
                c.label().c_str(), id.c_str(), a.receivers, a.maskDiffers, a.differing, a.sideDiffers, a.large,
                a.maxAbs, a.meanAbs);
  }
};

TEST_P(SpirvPath, HardVisibilitySameFilteredWithinTolerance) {
  const Case& c = GetParam();
  const Scene scene = test::bundledScene(c.scene);
  RenderSettings settings = test::renderSettings(c.size, c.mapSize);
  settings.path = c.path;
  // Each runner's own programs (G-buffer, shadow map) are built as it is constructed.
  const ShaderPathScope glslScope("glsl");
  FrameRunner glsl(scene, settings);
  std::unique_ptr<FrameRunner> spirv;
  {
    const ShaderPathScope spirvScope("spirv");
    spirv = std::make_unique<FrameRunner>(scene, settings);
  }
  ImageF truth;  // the GLSL path's ground truth, the first check's image
  const auto check = [&](const std::string& id, bool hard, const auto& run) {
    const ImageF a = run(glsl);
    ImageF b;
    {
      const ShaderPathScope spirvScope("spirv");
      b = run(*spirv);
    }
    const Agreement agreement = compare(a, b);
    report(c, id, agreement);
    EXPECT_GT(agreement.receivers, 0) << id;
    EXPECT_EQ(agreement.maskDiffers, 0) << id;
    if (truth.pixels.empty()) truth = a;
    if (hard) {
      SCOPED_TRACE(id);
      test::expectSameVisibilityAcrossPrograms(a, b, [&] { return truth; });
    }
    else if (id != "msm") EXPECT_LE(agreement.maxAbs, kFilteredMaxDifference) << id;
    else {
      EXPECT_LE(agreement.meanAbs, kMomentMeanDifference) << id;
      EXPECT_LE(agreement.large, kMomentLargeShare * agreement.receivers) << id;
    }
  };
  check("groundtruth", true, [](FrameRunner& runner) { return test::groundTruthVisibility(runner); });
  for (const RegisteredTechnique& technique : registeredTechniques()) {
    const std::string id = technique.info->id;
    check(id, technique.info->output == OutputKind::Hard,
          [&](FrameRunner& runner) { return test::runTechnique(runner, id).visibility; });
  }
}

// Small frames on every bundled scene, both paths: the programs and their variants are what
// matters here, a few tens of seconds in all on llvmpipe.
INSTANTIATE_TEST_SUITE_P(
    BundledScenes, SpirvPath,
    ::testing::Values(Case{"wall", {96, 54}, 256, TechniquePath::Fast}, Case{"bunny", {96, 54}, 256, TechniquePath::Fast},
                      Case{"fence", {96, 54}, 256, TechniquePath::Paper},
                      Case{"stacked_occluders", {96, 54}, 256, TechniquePath::Paper},
                      Case{"dragon_sun", {96, 54}, 256, TechniquePath::Fast}),
    [](const auto& info) { return test::caseName(info.param.label()); });

// The broader run behind docs/portability.md's figures (minutes):
//   testbed_tests --gtest_also_run_disabled_tests --gtest_filter='*DISABLED_Broad*'
INSTANTIATE_TEST_SUITE_P(
    DISABLED_Broad, SpirvPath,
    ::testing::ValuesIn([] {
      std::vector<Case> cases;
      for (const char* scene : {"wall", "bunny", "fence", "stacked_occluders", "dragon_sun"})
        for (TechniquePath path : {TechniquePath::Fast, TechniquePath::Paper}) {
          cases.push_back({scene, {320, 180}, 512, path});
          cases.push_back({scene, {640, 360}, 1024, path});
        }
      return cases;
    }()),
    [](const auto& info) { return test::caseName(info.param.label()); });

}  // namespace
}  // namespace testbed
