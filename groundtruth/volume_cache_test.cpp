// The ground truth keeps its shadow volumes across frames keyed on what they are made of
// (shadow_volumes.cpp, VolumeInputs): the meshes, the light, and each mesh's reach, which
// is all the camera can change. In a --frames run where only the camera moves (the fence
// dolly) they are built once or twice in 16 frames, and the last frame is still bit for bit
// the frame rendered alone; where the light moves (the sun sweep) every frame builds them.
#include "groundtruth/shadow_volumes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "testbed/harness/sequence.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

constexpr glm::ivec2 kSize{160, 90};
constexpr int kMapSize = 64;  // the shadow map plays no part in the ground truth

RenderSettings settingsOn(TechniquePath path) {
  RenderSettings settings = test::renderSettings(kSize, kMapSize);
  settings.path = path;
  return settings;
}

ParameterSet truthParameters() {
  return resolveParameters("groundtruth", shadowVolumeGroundTruth().info->parameters, {});
}

struct Sequence {
  std::uint64_t builds = 0;  // volume builds over the whole sequence
  int frames = 0;
  ImageF first, last;        // visibility of the first and the last frame
};

// Frames first..last (step) through one runner and one session, as runFrames drives them.
Sequence runSequence(const std::string& name, int last, int step, TechniquePath path) {
  Scene scene = test::bundledScene(name);
  FrameRunner runner(scene, settingsOn(path));
  TechniqueSession session(runner, shadowVolumeGroundTruth(), truthParameters());
  Sequence sequence;
  const std::uint64_t before = shadowVolumeBuilds();
  for (int frame = 0; frame <= last; frame += step) {
    advanceTo(scene, runner, frame);
    const TechniqueRun run = runner.run(session, truthParameters(), frame == 0);
    (frame == 0 ? sequence.first : sequence.last) = run.visibility;
    ++sequence.frames;
  }
  sequence.builds = shadowVolumeBuilds() - before;
  return sequence;
}

// Frame `frame` alone: the scene moved there before the runner and the instance exist.
ImageF frameAlone(const std::string& name, int frame, TechniquePath path) {
  Scene scene = test::bundledScene(name);
  applyFrame(scene, frame);
  FrameRunner runner(scene, settingsOn(path));
  runner.lightMoved();
  return runner.run(shadowVolumeGroundTruth(), truthParameters()).visibility;
}

int differingPixels(const ImageF& a, const ImageF& b) {
  EXPECT_EQ(a.pixels.size(), b.pixels.size());
  int differ = 0;
  for (std::size_t i = 0; i < std::min(a.pixels.size(), b.pixels.size()); ++i)
    differ += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
  return differ;
}

class VolumeCache : public ::testing::TestWithParam<TechniquePath> {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_P(VolumeCache, CameraOnlyFramesReuseTheVolumes) {
  const int last = 45, step = 3;
  const Sequence dolly = runSequence("motion/fence_dolly", last, step, GetParam());
  EXPECT_EQ(dolly.frames, 16);
  // Depth-fail volumes (the paper path) never depend on the camera: one build. Depth-pass
  // ones (the fast path) end on the floor's plane whatever the camera does, but once the
  // camera stands over the floor its near plane may clip it, and the floor keeps its light
  // caps from then on: a second build. (Keyed on the camera's bounds instead, 14 of the 16
  // frames built them.)
  EXPECT_EQ(dolly.builds, GetParam() == TechniquePath::Paper ? 1u : 2u);
  EXPECT_EQ(differingPixels(dolly.last, frameAlone("motion/fence_dolly", last, GetParam())), 0);
  // The camera moved: the first frame's image differs, so the comparison above can fail.
  EXPECT_GT(differingPixels(dolly.first, dolly.last), 0);
}

TEST_P(VolumeCache, LightFramesBuildTheVolumesAgain) {
  const Sequence sweep = runSequence("motion/dragon_sun_sweep", 6, 2, GetParam());
  EXPECT_EQ(sweep.builds, std::uint64_t(sweep.frames));
  EXPECT_EQ(differingPixels(sweep.last, frameAlone("motion/dragon_sun_sweep", 6, GetParam())), 0);
}

INSTANTIATE_TEST_SUITE_P(Paths, VolumeCache, ::testing::Values(TechniquePath::Paper, TechniquePath::Fast),
                         [](const auto& info) { return std::string(pathName(info.param)); });

}  // namespace
}  // namespace testbed
