// Stability across arithmetic (testbed/harness/stability.h, docs/conformance.md): on the
// bundled scenes, small frames, every technique at its defaults keeps the visibility of
// receivers 3 px or more from the ground truth's boundary when the compiler path changes
// (GLSL <-> SPIR-V) and when the light moves by 4 float ulps. Also the check's parts on
// planted images, and a known unstable set-up (msm without its depth bias) that it must
// catch, so the check can fail.
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "groundtruth/shadow_volumes.h"
#include "testbed/harness/stability.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// A w×h image lit left of column `edge`, shadowed from it on.
ImageF halfLit(int w, int h, int edge) {
  ImageF image;
  image.width = w;
  image.height = h;
  image.channels = 1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.pixels.push_back(x < edge ? 1.0f : 0.0f);
  return image;
}

TEST(Stability, FarFromBoundaryStartsAtTheStatedDistance) {
  // Boundary pixels: columns 9 (lit) and 10 (shadow). Column 6 lies 3 px from column 9.
  const ImageF image = halfLit(20, 4, 10);
  const auto far = farFromBoundary(image, 3);
  for (int x = 0; x < 20; ++x) {
    const bool expected = x <= 6 || x >= 13;
    EXPECT_EQ(far[std::size_t(x)], expected) << "column " << x;
  }
}

TEST(Stability, BackgroundIsNeverJudgedAndNoBoundaryMeansAllFar) {
  ImageF image = halfLit(8, 2, 8);  // all lit: no boundary
  image.pixels[3] = kNaN;
  const auto far = farFromBoundary(image, 3);
  for (std::size_t i = 0; i < far.size(); ++i) EXPECT_EQ(far[i], i != 3) << i;
}

TEST(Stability, CompareCountsChangesAndFlipsOnJudgedReceiversOnly) {
  const ImageF before = halfLit(4, 1, 2);  // 1 1 0 0
  ImageF after = before;
  // No change; a change and a flip; a change and a flip; a change within the limit that
  // crosses 0.5 (a filtered value at the threshold: crossed, not flipped).
  after.pixels = {0.995f, 0.2f, 0.6f, 0.0f};
  ImageF atHalf = before;
  atHalf.pixels[3] = 0.4995f;
  after.pixels[3] = 0.5005f;
  const auto all = compareVisibility("planted", atHalf, after, {true, true, true, true}, 0.01);
  EXPECT_EQ(all.judged, 4);
  EXPECT_EQ(all.changed, 2);
  EXPECT_EQ(all.flipped, 2);
  EXPECT_EQ(all.crossed, 3);
  EXPECT_FLOAT_EQ(float(all.maxChange), 0.8f);
  EXPECT_EQ(all.example.rfind("pixel (1, 0)", 0), 0u) << all.example;
  const auto some = compareVisibility("planted", before, after, {true, false, false, false}, 0.01);
  EXPECT_EQ(some.judged, 1);
  EXPECT_EQ(some.changed + some.flipped + some.crossed, 0);
}

TEST(Stability, NudgedLightMovesByAFewUlpsAndSurvivesNormalization) {
  LightDesc sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  const glm::vec3 d = nudgedLight(sun, 4).direction;
  EXPECT_NE(glm::normalize(d), glm::normalize(sun.direction));
  EXPECT_LT(glm::length(d - sun.direction), 1e-6f);
  LightDesc spot;
  spot.eye = {6, 40, 4};
  const LightDesc moved = nudgedLight(spot, 4);
  EXPECT_NE(moved.eye, spot.eye);
  EXPECT_LT(glm::length(moved.eye - spot.eye), 1e-4f);
  EXPECT_EQ(moved.direction, spot.direction);
}

struct Case {
  std::string scene;
  TechniquePath path;
  std::string label() const { return scene + "_" + std::string(pathName(path)); }
  friend void PrintTo(const Case& c, std::ostream* out) { *out << c.label(); }
};

class StabilityScenes : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override { test::sharedContext(); }
};

// Small frames: the check is about arithmetic, not resolution (about a minute in all on
// llvmpipe, both paths' programs built per technique).
RenderSettings smallFrame(TechniquePath path) {
  RenderSettings settings = test::renderSettings({160, 90}, 256);
  settings.path = path;
  return settings;
}

TEST_P(StabilityScenes, NoFarReceiverChangesOrFlips) {
  const Case& c = GetParam();
  const Scene scene = test::bundledScene(c.scene);
  for (const RegisteredTechnique& technique : registeredTechniques()) {
    const std::string& id = technique.info->id;
    const auto parameters = resolveParameters(id, technique.info->parameters, {});
    const StabilityReport report =
        measureStability(scene, smallFrame(c.path), technique, parameters, shadowVolumeGroundTruth());
    std::printf("stability %s %s: %s\n", c.label().c_str(), id.c_str(), report.summary().c_str());
    for (const auto& count : report.counts) EXPECT_GT(count.judged + int(count.skipped), 0) << id;
    EXPECT_EQ(report.flipped(), 0) << id << ": " << report.summary();
    EXPECT_EQ(report.changed(), 0) << id << ": " << report.summary();
  }
}

INSTANTIATE_TEST_SUITE_P(BundledScenes, StabilityScenes,
                         ::testing::Values(Case{"wall", TechniquePath::Fast}, Case{"bunny", TechniquePath::Fast},
                                           Case{"fence", TechniquePath::Paper},
                                           Case{"stacked_occluders", TechniquePath::Paper},
                                           Case{"dragon_sun", TechniquePath::Fast}),
                         [](const auto& info) { return test::caseName(info.param.label()); });

// msm's settings before its depth bias and its larger moment bias: the paper's comparison
// as is, with the paper's α for 16-bit storage (Peters & Klein, I3D 2015).
const std::map<std::string, std::string> kMsmPaperBias = {{"depth_bias", "0"}, {"moment_bias", "3e-5"}};

// Totals of one technique's reports over the CI's bundled-scene cases.
StabilityReport overBundledScenes(const std::string& id, const std::map<std::string, std::string>& set) {
  const RegisteredTechnique& technique = findTechnique(id);
  const auto parameters = resolveParameters(id, technique.info->parameters, set);
  StabilityReport total;
  for (const Case& c : {Case{"wall", TechniquePath::Fast}, Case{"bunny", TechniquePath::Fast},
                        Case{"fence", TechniquePath::Paper}, Case{"stacked_occluders", TechniquePath::Paper},
                        Case{"dragon_sun", TechniquePath::Fast}}) {
    const Scene scene = test::bundledScene(c.scene);
    const StabilityReport report =
        measureStability(scene, smallFrame(c.path), technique, parameters, shadowVolumeGroundTruth());
    total.counts.insert(total.counts.end(), report.counts.begin(), report.counts.end());
  }
  return total;
}

// The check can fail: msm with the paper's bias alone, on the same frames, changes far
// receivers by more than 0.01 (6 of them on llvmpipe, none at its defaults;
// docs/techniques.md, "Moment shadow maps").
TEST(Stability, MsmWithThePapersBiasAloneIsCaught) {
  test::sharedContext();
  const StabilityReport report = overBundledScenes("msm", kMsmPaperBias);
  std::printf("stability msm with the paper's bias alone: %d changed, %d flipped\n", report.changed(),
              report.flipped());
  EXPECT_GT(report.changed(), 0);
}

// The figures behind docs/techniques.md's "Moment shadow maps": msm with the paper's bias
// alone and at its defaults, on the broad runs of tests/spirv_path_test.cpp (the five
// scenes at 320×180 / 512², both paths), over every receiver (0 px: the figures
// docs/portability.md gives) and over those 3 px or more from a boundary. About a minute:
//   testbed_tests --gtest_also_run_disabled_tests --gtest_filter='*DISABLED_MsmBiasFigures*'
TEST(Stability, DISABLED_MsmBiasFigures) {
  test::sharedContext();
  const RegisteredTechnique& msm = findTechnique("msm");
  for (const bool paper : {true, false}) {
    for (const double farPx : {0.0, 3.0}) {
      int judged = 0, changedPath = 0, flippedPath = 0, crossedPath = 0, changedLight = 0, flippedLight = 0;
      for (const char* name : {"wall", "bunny", "fence", "stacked_occluders", "dragon_sun"})
        for (TechniquePath path : {TechniquePath::Fast, TechniquePath::Paper}) {
          const Scene scene = test::bundledScene(name);
          RenderSettings settings = test::renderSettings({320, 180}, 512);
          settings.path = path;
          const auto parameters = resolveParameters("msm", msm.info->parameters,
                                                    paper ? kMsmPaperBias : std::map<std::string, std::string>{});
          StabilityOptions options;
          options.farPx = farPx;
          const StabilityReport report =
              measureStability(scene, settings, msm, parameters, shadowVolumeGroundTruth(), options);
          judged += report.counts[0].judged;
          changedPath += report.counts[0].changed;
          flippedPath += report.counts[0].flipped;
          crossedPath += report.counts[0].crossed;
          changedLight += report.counts[1].changed;
          flippedLight += report.counts[1].flipped;
        }
      std::printf("msm %s, receivers >= %g px from a boundary: %d judged; shader path: %d changed, %d flipped "
                  "(%d across 0.5 by any amount); light +4 ulp: %d changed, %d flipped\n",
                  paper ? "with the paper's bias alone" : "at its defaults", farPx, judged, changedPath,
                  flippedPath, crossedPath, changedLight, flippedLight);
    }
  }
}

}  // namespace
}  // namespace testbed
