// Techniques that derive data from the scene's geometry and keep it across frames
// (silhouette-map its mesh adjacency, the prefiltered family its object boxes) key it on
// Scene::geometryRevision (docs/motion.md "Running a sequence: --frames"). With an object
// that moves, frame k rendered inside a sequence must then be bit for bit frame k rendered
// by a fresh instance on a fresh runner: a cache keyed on anything less would keep the
// frame-0 geometry and differ.
#include <cmath>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "testbed/harness/sequence.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

using test::bundledScene;
using test::renderSettings;
using test::sharedContext;

// Tiny, and a frame late enough for the blade to have turned far from frame 0's pose.
constexpr glm::ivec2 kSize{96, 64};
constexpr int kMapSize = 128;
constexpr int kFrame = 20;

// Pixels whose bits differ (NaN against NaN counts as equal: no receiver in both).
int differingPixels(const ImageF& a, const ImageF& b) {
  if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) return -1;
  int differing = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    if (std::isnan(a.pixels[i]) && std::isnan(b.pixels[i])) continue;
    differing += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
  }
  return differing;
}

// Frames 0..kFrame through one runner and one instance, as runSequence drives them.
ImageF frameInSequence(const std::string& id) {
  Scene scene = bundledScene("motion/spinning_occluder");
  FrameRunner runner(scene, renderSettings(kSize, kMapSize));
  const auto& technique = findTechnique(id);
  const ParameterSet parameters = resolveParameters(id, technique.info->parameters, {});
  TechniqueSession session(runner, technique, parameters);
  TechniqueRun run;
  for (int frame = 0; frame <= kFrame; ++frame) {
    advanceTo(scene, runner, frame);
    run = runner.run(session, parameters, frame == 0);
  }
  return run.visibility;
}

// Frame kFrame alone: the scene moved there before the runner and the instance exist.
ImageF frameAlone(const std::string& id) {
  Scene scene = bundledScene("motion/spinning_occluder");
  applyFrame(scene, kFrame);
  FrameRunner runner(scene, renderSettings(kSize, kMapSize));
  runner.lightMoved();
  return test::runTechnique(runner, id).visibility;
}

class SceneDerivedCache : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override { sharedContext(); }
};

TEST_P(SceneDerivedCache, FrameInASequenceIsTheFrameRenderedAlone) {
  const ImageF inSequence = frameInSequence(GetParam()), alone = frameAlone(GetParam());
  EXPECT_EQ(differingPixels(inSequence, alone), 0);
  // The blade moved: frame 0 differs, so the comparison above can fail.
  Scene still = bundledScene("motion/spinning_occluder");
  FrameRunner runner(still, renderSettings(kSize, kMapSize));
  EXPECT_GT(differingPixels(test::runTechnique(runner, GetParam()).visibility, alone), 0);
}

INSTANTIATE_TEST_SUITE_P(Motion, SceneDerivedCache, ::testing::Values("silhouette-map", "msm", "vsm"),
                         [](const auto& info) { return test::caseName(info.param); });

}  // namespace
}  // namespace testbed
