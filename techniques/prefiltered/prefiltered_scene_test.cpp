// The pre-filtered techniques through the full pipeline (G-buffer, moments, blur,
// visibility) against the shadow-volume ground truth: the papers' light-leaking ordering
// (in leak_pct on stacked_occluders.json; on the bundled wall.json only below leak_pct's
// threshold, see there), and finite visibility everywhere, including extreme depth ranges.
// The tables printed are the figures the reports quote.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/metrics/metrics.h"
#include "testbed/scene/scene.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

using test::bundledScene;
using test::runTechnique;

RenderSettings testSettings() { return test::renderSettings({640, 360}, 1024); }

struct Figures {
  ErrorMetrics error;
  double bleedPct = 0;  // leak_pct with the threshold lowered from 0.5 to 0.1
  double gpuMs = 0;
};

// leak_pct counts deep-shadow pixels (ground-truth shadow, beyond the margin from its
// boundaries) with v > 0.5. The same count with v > threshold: the metric on v + (0.5 −
// threshold), which moves nothing but the technique's values.
double leakAbove(const ImageF& visibility, const ImageF& truth, float threshold) {
  // leak_pct counts v > 0.5; mapping v > threshold to 1 and the rest to 0 moves its
  // threshold while keeping every value in [0, 1], which the metrics require.
  ImageF crossed = visibility;
  for (float& v : crossed.pixels)
    if (!std::isnan(v)) v = v > threshold ? 1.0f : 0.0f;
  return computeErrorMetrics(crossed, truth).leakPct;
}

const std::vector<std::string> kCompared{"sm", "vsm", "esm", "evsm", "msm"};

// Every technique (defaults) against the ground truth on `scene`, printed as a table.
std::map<std::string, Figures> compare(const Scene& scene, const std::string& label) {
  FrameRunner runner(scene, testSettings());
  const TechniqueRun truth = runner.run(shadowVolumeGroundTruth(), resolveParameters("groundtruth", {}, {}));
  std::map<std::string, Figures> figures;
  for (const auto& id : kCompared) {
    const TechniqueRun run = runTechnique(runner, id);
    figures[id] = {computeErrorMetrics(run.visibility, truth.visibility), leakAbove(run.visibility, truth.visibility, 0.1f),
                   run.times.totalMs};
  }
  std::cout << label << " 640x360, map 1024 (llvmpipe):\n"
            << "  technique  leak_pct  leak_pct(v>0.1)  mismatch_pct  overest_pct  boundary_mean  rmse  gpu_x_sm\n"
            << std::fixed << std::setprecision(3);
  for (const auto& id : kCompared) {
    const Figures& f = figures[id];
    std::cout << "  " << std::setw(9) << id << "  " << std::setw(8) << f.error.leakPct << "  " << std::setw(15)
              << f.bleedPct << "  " << std::setw(12) << f.error.mismatchPct << "  " << std::setw(11)
              << f.error.overestimationPct << "  " << std::setw(13) << f.error.boundaryMean << "  " << f.error.rmse
              << "  " << f.gpuMs / figures["sm"].gpuMs << "\n";
  }
  std::cout.unsetf(std::ios::floatfield);
  return figures;
}

class PrefilteredScenes : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_F(PrefilteredScenes, StackedOccludersLeakOrderingFollowsThePapers) {
  // VSM's light bleeding (stacked_occluders.json): a far occluder's edge over a near one,
  // the receiver close behind the near one. Chebyshev's bound leaks well above 0.5 there;
  // the exponential warps (EVSM) and four moments (MSM) recover the near occluder.
  auto f = compare(bundledScene("stacked_occluders"), "stacked-occluders");
  const double sm = f["sm"].error.leakPct, vsm = f["vsm"].error.leakPct;
  EXPECT_GT(vsm, sm + 2.0) << "VSM should leak visibly more than plain shadow mapping";
  EXPECT_LT(f["evsm"].error.leakPct, 0.25 * vsm) << "EVSM should leak far less than VSM";
  EXPECT_LT(f["msm"].error.leakPct, vsm) << "MSM should leak less than VSM";
}

TEST_F(PrefilteredScenes, WallBleedsOnlyBelowTheLeakThreshold) {
  // The papers' leak case as the bundled wall.json builds it: the wall hides all of the box
  // from the light but a strip of its top, and the wall's top edge crosses that strip in
  // the map, so the floor in the box's shadow sees the wall (far) and the box (near) in one
  // kernel. But that floor lies 6 high behind the box's top and the box 19 units behind the
  // wall's: with w of the kernel on the wall, Chebyshev's bound there is
  // w(1 − w) / (w(1 − w) + (r + w)²), r = 8.4/19.5 = 0.43, at most 0.29 (measured: below 0.2
  // beyond the margin), so the bleeding is real yet leak_pct (v > 0.5)
  // cannot see it, for any of the techniques. Measured with v > 0.1 the papers' ordering
  // shows: VSM bleeds, EVSM and MSM do not. (ESM bleeds most at v > 0.1 here: its
  // contact leak where the floor meets the wall's base, which is not a case the papers'
  // ordering is about.) stacked_occluders.json is the scene that shows it in leak_pct.
  auto f = compare(bundledScene("wall"), "wall");
  for (const auto& id : kCompared) EXPECT_EQ(f[id].error.leakPct, 0.0) << id;
  const double vsm = f["vsm"].bleedPct;
  EXPECT_GT(vsm, f["sm"].bleedPct) << "VSM should bleed where plain shadow mapping does not";
  EXPECT_LT(f["evsm"].bleedPct, 0.25 * vsm) << "EVSM should bleed far less than VSM";
  EXPECT_LT(f["msm"].bleedPct, vsm) << "MSM should bleed less than VSM";
}

// A receiver pixel's value must be a number in [0, 1]; background pixels are NaN by contract.
int countBadReceivers(const TechniqueRun& run, const ImageF& positions, std::string& first) {
  int bad = 0;
  for (int y = 0; y < positions.height; ++y)
    for (int x = 0; x < positions.width; ++x) {
      if (positions.at(x, y, 3) < 0.5f) continue;
      const float v = run.visibility.at(x, y);
      if (std::isfinite(v) && v >= 0.0f && v <= 1.0f) continue;
      if (bad++ == 0) first = "(" + std::to_string(x) + ", " + std::to_string(y) + ") = " + std::to_string(v);
    }
  return bad;
}

struct Variant {
  std::string id;
  std::map<std::string, std::string> parameters;
};

const std::vector<Variant>& everyStorage() {
  static const std::vector<Variant> variants{
      {"vsm", {}},
      {"esm", {}},
      {"evsm", {{"moments", "2"}}},
      {"evsm", {{"moments", "4"}}},
      {"msm", {{"storage", "16"}}},
      {"msm", {{"storage", "32"}}},
      {"msm", {{"storage", "16"}, {"mips", "true"}, {"blur", "5"}}},
      {"evsm", {{"positive_exponent", "42"}, {"negative_exponent", "42"}, {"mips", "true"}}},
      {"esm", {{"exponent", "88"}, {"blur", "1"}}},
  };
  return variants;
}

void expectFiniteEverywhere(const Scene& scene, const std::string& label) {
  FrameRunner runner(scene, testSettings());
  int receivers = 0;
  for (int i = 0; i < runner.positions().width * runner.positions().height; ++i)
    receivers += runner.positions().pixels[std::size_t(i) * 4 + 3] >= 0.5f;
  ASSERT_GT(receivers, 1000) << label;
  for (const Variant& variant : everyStorage()) {
    const TechniqueRun run = runTechnique(runner, variant.id, variant.parameters);
    std::string first;
    const int bad = countBadReceivers(run, runner.positions(), first);
    std::string name = variant.id;
    for (const auto& [k, v] : variant.parameters) name += " " + k + "=" + v;
    EXPECT_EQ(bad, 0) << label << ", " << name << ": " << bad << " receivers not in [0, 1], first " << first;
  }
}

TEST_F(PrefilteredScenes, VisibilityIsFiniteOnEveryBundledScene) {
  for (const char* name : {"wall", "fence", "bunny", "dragon_sun"}) expectFiniteEverywhere(bundledScene(name), name);
}

TEST_F(PrefilteredScenes, VisibilityIsFiniteWithAHugeDepthRange) {
  // Near 0.01, far 1e5: the whole scene sits within the first 0.1% of the normalized depth.
  Scene scene = bundledScene("wall");
  scene.light.nearPlane = 0.01f;
  scene.light.farPlane = 1e5f;
  expectFiniteEverywhere(scene, "wall, light near 0.01 far 1e5");
}

TEST_F(PrefilteredScenes, VisibilityIsFiniteWithDepthsAtBothEndsOfTheRange) {
  // Near and far planes fitted to the scene's extent along the light's axis, so occluders
  // touch depth 0 and receivers reach depth 1 (and the farthest corners lie beyond it).
  Scene scene = bundledScene("wall");
  const glm::vec3 eye = scene.light.eye, axis = glm::normalize(scene.light.target - scene.light.eye);
  float nearest = 1e30f, farthest = 0.0f;
  for (const auto& object : scene.objects)
    for (const auto v : object.mesh.vertices()) {
      const auto& p = object.mesh.point(v);
      const float d = glm::dot(glm::vec3(p[0], p[1], p[2]) - eye, axis);
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
    }
  scene.light.nearPlane = nearest * 0.9999f;
  scene.light.farPlane = 0.5f * (nearest + farthest) + 0.3f * (farthest - nearest);
  expectFiniteEverywhere(scene, "wall, near/far fitted to the scene");
}

}  // namespace
}  // namespace testbed
