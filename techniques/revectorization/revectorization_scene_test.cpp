// Scene-level tests of the revectorization family against the shadow-volume ground truth
// on the bundled scenes at 640×360 with 256² and 512² maps. Every figure is printed for
// the closing note.
//
// What the data says (and these tests assert): improved SMSR (EDTSM* eq. 7) beats sm on
// edge_mismatch_pct everywhere but on axis-aligned thin stripes (stacked_occluders, see
// below); conservative SMSR (eq. 4, the GI 2016 function and smsr's
// default) does not: on an ideal staircase its line is the true line moved half a texel
// into the lit side (RevectorizationGlsl.ConservativeLineIsTheTrueLineHalfATexelIntoTheLitSide),
// so its boundary error is larger than sm's stair; its figures are printed, not asserted
// against sm. Improved overestimates less than conservative, which overestimates more
// than sm (both measured next to the boundary, where they differ); the filtered variants
// add no leak except RSMSS's opened stripe tips on stacked_occluders.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>

#include "testbed/harness/frame_runner.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

using Assignments = std::map<std::string, std::string>;

// The contract's metrics, plus overestimation over every GT-lit pixel but the boundary
// pixels themselves (margin 0.5 px): the default 8 px margin hides the sub-texel
// overestimation that tells the two SMSR visibility functions apart.
struct Measured {
  ErrorMetrics m;
  double overestimationNearPct = 0;
};

Measured measure(FrameRunner& runner, const ImageF& truth, const std::string& id, const Assignments& set,
                 const std::string& label, const std::string& scene, int mapSize) {
  const ImageF v = test::runTechnique(runner, id, set).visibility;
  Measured r{computeErrorMetrics(v, truth), computeErrorMetrics(v, truth, nullptr, {.marginPx = 0.5}).overestimationPct};
  const ErrorMetrics& m = r.m;
  char line[260];
  std::snprintf(line, sizeof line, "%-10s %4d  %-18s %8.3f %7.2f %9.3f %9.3f %7.3f %7.3f %9.3f %8.4f\n",
                scene.c_str(), mapSize, label.c_str(), m.mismatchPct, m.edgeMismatchPct, m.boundaryMean, m.boundaryP95,
                m.leakPct, m.overestimationPct, r.overestimationNearPct, m.rmse);
  std::cout << line << std::flush;
  return r;
}

class RevectorizationScene : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_F(RevectorizationScene, AgainstShadowVolumesOnTheBundledScenes) {
  std::cout << "scene      map   technique          mismatch%  edge%  bnd_mean   bnd_p95   leak%  overest%  "
               "over@0.5px rmse\n";
  for (const std::string name : {"bunny", "wall", "fence", "dragon_sun", "stacked_occluders"})
    for (const int mapSize : {256, 512}) {
      SCOPED_TRACE(name + " " + std::to_string(mapSize));
      const Scene scene = test::bundledScene(name);
      FrameRunner runner(scene, test::renderSettings({640, 360}, mapSize));
      const ImageF truth = test::groundTruthVisibility(runner);
      auto run = [&](const std::string& id, const Assignments& set, const std::string& label) {
        return measure(runner, truth, id, set, label, name, mapSize);
      };
      const Measured sm = run("sm", {}, "sm");
      const Measured conservative = run("smsr", {}, "smsr");
      const Measured improved = run("smsr", {{"visibility", "improved"}}, "smsr improved");
      const Measured twoPass = run("smsr-2pass", {}, "smsr-2pass");
      const Measured rsmss = run("rsmss", {}, "rsmss");
      const Measured rpcfSmsr = run("rpcf-smsr", {}, "rpcf-smsr");
      const Measured rpcfRsmss = run("rpcf-rsmss", {}, "rpcf-rsmss");

      // stacked_occluders: shadows of thin bars (2.5 texels at 256²) at a small angle to a
      // map axis. A tip texel is a U across the stripe and an L along it, which RSMSS's
      // r_x·r_y < 0 rule lights almost fully (a leak), and improved SMSR closes the lit
      // notches between the stripes: figures printed, not asserted against sm (docs/techniques.md,
      // "Revectorization: what the bundled scenes show").
      const bool axisAlignedStripes = name == "stacked_occluders";
      if (!axisAlignedStripes) {
        EXPECT_LT(improved.m.edgeMismatchPct, sm.m.edgeMismatchPct);
        EXPECT_LE(rsmss.m.leakPct, sm.m.leakPct);
        EXPECT_LE(rpcfRsmss.m.leakPct, sm.m.leakPct);
      }
      EXPECT_LE(improved.m.overestimationPct, conservative.m.overestimationPct);
      // Near the boundary, where the two functions differ, improved overestimates strictly
      // less (EDTSM*'s claim); conservative overestimates more than sm's stair there.
      EXPECT_LT(improved.overestimationNearPct, conservative.overestimationNearPct);
      EXPECT_GT(conservative.overestimationNearPct, sm.overestimationNearPct);
      // Conservative SMSR only adds shadow: it cannot leak where sm does not.
      EXPECT_LE(conservative.m.leakPct, sm.m.leakPct);
      EXPECT_LE(twoPass.m.leakPct, sm.m.leakPct);
      // The same clipping measured in screen space instead of light space.
      EXPECT_LT(std::abs(twoPass.m.edgeMismatchPct - conservative.m.edgeMismatchPct),
                0.25 * conservative.m.edgeMismatchPct);
      EXPECT_LE(rpcfSmsr.m.leakPct, sm.m.leakPct);
    }
}

// The same frame through the real screen passes: kernel 1 is the base technique exactly.
TEST_F(RevectorizationScene, RpcfKernelOneEqualsItsBaseOnAScene) {
  const Scene scene = test::bundledScene("bunny");
  FrameRunner runner(scene, test::renderSettings({320, 180}, 256));
  auto visibility = [&](const std::string& id, const Assignments& set) {
    return test::runTechnique(runner, id, set).visibility;
  };
  auto same = [](const ImageF& a, const ImageF& b) {
    int differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
      differing += !(a.pixels[i] == b.pixels[i] || (std::isnan(a.pixels[i]) && std::isnan(b.pixels[i])));
    return differing;
  };
  EXPECT_EQ(same(visibility("rpcf-smsr", {{"kernel", "1"}}), visibility("smsr", {})), 0);
  EXPECT_EQ(same(visibility("rpcf-rsmss", {{"kernel", "1"}}), visibility("rsmss", {})), 0);
}

// Debug views: asked for, they come back as named RGB images of the screen's size with
// some coloured (edge) pixels; not asked for, there are none. smsr-2pass shows its own
// screen-space map, which on lit receivers holds the same d_c as smsr's light-space view.
TEST_F(RevectorizationScene, DebugViewsAreReturnedOnlyWhenAsked) {
  const Scene scene = test::bundledScene("bunny");
  FrameRunner runner(scene, test::renderSettings({320, 180}, 256));
  std::map<std::string, ImageF> views;
  for (const std::string id : {"smsr", "smsr-2pass"}) {
    SCOPED_TRACE(id);
    EXPECT_TRUE(test::runTechnique(runner, id).debugImages.empty());
    for (const std::string view : {"discontinuity", "onds"}) {
      const auto run = test::runTechnique(runner, id, {{"debug", view}});
      ASSERT_EQ(run.debugImages.size(), 1u);
      EXPECT_EQ(run.debugImages[0].first, view);
      const ImageF& image = run.debugImages[0].second;
      EXPECT_EQ(image.width, 320);
      EXPECT_EQ(image.height, 180);
      EXPECT_EQ(image.channels, 3);
      int coloured = 0;
      for (const float v : image.pixels) coloured += v > 0.0f;
      EXPECT_GT(coloured, 10);
      views[id + "." + view] = image;
    }
  }
  const ImageF& single = views["smsr.discontinuity"];
  const ImageF& two = views["smsr-2pass.discontinuity"];
  int litEdges = 0, differing = 0;
  for (std::size_t i = 0; i < two.pixels.size(); i += 3) {
    if (two.pixels[i + 2] != 0.0f) continue;  // b = 1 − s: shadowed receivers
    litEdges += two.pixels[i] > 0.0f || two.pixels[i + 1] > 0.0f;
    differing += two.pixels[i] != single.pixels[i] || two.pixels[i + 1] != single.pixels[i + 1];
  }
  EXPECT_GT(litEdges, 10);
  EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace testbed
