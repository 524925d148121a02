// Depth-pass counting (chosen where the eye is in no volume, with sides ending on a far
// plane, light caps only where the near plane clips, twin sides drawn once and a depth
// pre-test) against depth-fail counting
// with closed volumes to infinity and no pre-test, the straightforward path: the same
// visibility wherever the eye is outside every volume (bit for bit on llvmpipe,
// test::expectSameVisibilityAcrossPrograms). And the choice itself
// on a camera in shadow.
#include "groundtruth/shadow_volumes.h"

#include <gtest/gtest.h>

#include <string>

#include "groundtruth/hard_case_scenes.h"
#include "groundtruth/volume_geometry.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/scene/view.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"

namespace testbed {
namespace {

using test::directional;
using test::spot;

TechniqueRun run(FrameRunner& runner, const RegisteredTechnique& technique) {
  return runner.run(technique, resolveParameters("groundtruth", technique.info->parameters, {}));
}

bool eyeInAnyVolume(const Scene& scene) {
  const LightTransforms light = lightTransforms(scene.light);
  const VolumeLight volumeLight{light.orthographic, light.position, light.direction};
  for (const auto& object : scene.objects)
    if (eyeMayBeInVolume(volumeMesh(meshTopology(object.mesh)), volumeLight, scene.camera.eye, 1e4f)) return true;
  return false;
}

class DepthPassCounting : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
  static void expectSameAsDepthFail(const Scene& scene) {
    ASSERT_FALSE(eyeInAnyVolume(scene)) << scene.name << ": the eye must be outside every volume";
    RenderSettings settings;
    settings.size = {320, 180};
    FrameRunner runner(scene, settings);
    const TechniqueRun automatic = run(runner, shadowVolumeGroundTruth());
    const TechniqueRun depthFail = run(runner, depthFailGroundTruth());
    int shadowed = 0;
    for (float v : depthFail.visibility.pixels) shadowed += v == 0.0f;
    EXPECT_GT(shadowed, 0) << scene.name << ": no shadow, the comparison would prove nothing";
    SCOPED_TRACE(scene.name);
    test::expectSameVisibilityAcrossPrograms(automatic.visibility, depthFail.visibility,
                                             [&] { return depthFail.visibility; });
  }
};

TEST_F(DepthPassCounting, BundledScenesMatchDepthFail) {
  for (const char* name : {"bunny", "dragon_sun", "fence", "stacked_occluders", "wall"})
    expectSameAsDepthFail(test::bundledScene(name));
}

TEST_F(DepthPassCounting, SpotAndDirectionalBoxesMatchDepthFail) {
  expectSameAsDepthFail(test::boxOverPlane(spot({0, 40, 0}, 60)));
  expectSameAsDepthFail(test::boxOverPlane(directional({0.4f, -1, 0.2f})));
}

TEST_F(DepthPassCounting, OpenMeshesMatchDepthFail) {
  // Open meshes have volumes for both facings and twin sides on their silhouettes.
  expectSameAsDepthFail(test::openMeshesScene());
}

TEST_F(DepthPassCounting, AnOccluderCrossingTheNearPlaneMatchesDepthFail) {
  // The camera's near plane clips a bar away: the G-buffer shows the floor through it, so
  // depth-pass must meet the bar's light caps between the eye and the floor.
  expectSameAsDepthFail(test::nearPlaneScene());
}

TEST(DepthPassChoice, AnEyeInShadowChoosesDepthFail) {
  // The camera under a wide slab is inside its volume: depth-pass would miss the slab's
  // volume there.
  Scene scene = test::cameraInVolumeScene();
  EXPECT_TRUE(eyeInAnyVolume(scene));
  // Beside the slab, in the light, the eye is outside every volume.
  scene.camera.eye = {40, 6, -2};
  EXPECT_FALSE(eyeInAnyVolume(scene));
  // A spot light: the eye behind the slab from the light is in shadow, above it is not.
  scene.light = spot({0, 40, 0}, 90);
  scene.camera.eye = {1, 6, 1};
  EXPECT_TRUE(eyeInAnyVolume(scene));
  scene.camera.eye = {1, 30, 1};
  EXPECT_FALSE(eyeInAnyVolume(scene));
}

TEST_F(DepthPassCounting, AnEyeInShadowGivesTheDepthFailImage) {
  // Depth-pass here would be off by the slab: the choice must fall to depth-fail.
  const Scene scene = test::cameraInVolumeScene();
  ASSERT_TRUE(eyeInAnyVolume(scene));
  RenderSettings settings;
  settings.size = {320, 180};
  FrameRunner runner(scene, settings);
  // The same programs on the same inputs: equal bit for bit on any implementation.
  EXPECT_EQ(test::differingPixels(run(runner, shadowVolumeGroundTruth()).visibility,
                                  run(runner, depthFailGroundTruth()).visibility),
            0);
}

}  // namespace
}  // namespace testbed
