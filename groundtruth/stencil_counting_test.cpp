// The ground truth's two paths (stencil_counting.h, docs/paths.md): on the paper path the
// stencil shadow volumes GI 2016 ranks against (capped volumes, depth-fail, one two-sided
// stencil pass) give the fast path's blended counts' visibility (bit for bit on llvmpipe,
// test::expectSameVisibilityAcrossPrograms), on every
// bundled scene at two sizes, on hard cases, and with the camera inside a shadow volume,
// where depth-pass counting is wrong. Each run times its own variant's pass, and the
// ground truth renders within its declaration: the passes and resources of its path.
#include "groundtruth/shadow_volumes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "groundtruth/hard_case_scenes.h"
#include "groundtruth/stencil_counting.h"
#include "testbed/harness/frame_runner.h"
#include "tests/gl_fixture.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;

TechniqueRun render(const Scene& scene, glm::ivec2 size, TechniquePath path,
                    const RegisteredTechnique& technique = shadowVolumeGroundTruth()) {
  RenderSettings settings = test::renderSettings(size, 64);  // the shadow map plays no part
  settings.path = path;
  FrameRunner runner(scene, settings);
  return runner.run(technique, resolveParameters("groundtruth", technique.info->parameters, {}));
}

bool timed(const TechniqueRun& run, const std::string& pass) {
  return std::find(run.times.order.begin(), run.times.order.end(), pass) != run.times.order.end();
}

// The paper path's image is the fast path's, the scene has shadow and lit receivers (else
// the comparison proves little), and each path ran its own counting.
void expectPathsAgree(const Scene& scene, glm::ivec2 size) {
  SCOPED_TRACE(scene.name + " at " + std::to_string(size.x) + "x" + std::to_string(size.y));
  const TechniqueRun paper = render(scene, size, TechniquePath::Paper);
  const TechniqueRun fast = render(scene, size, TechniquePath::Fast);
  const test::Receivers receivers = test::receiversOf(fast.visibility);
  EXPECT_GT(receivers.fullyShadowed, 0);
  EXPECT_LT(receivers.fullyShadowed, receivers.count);
  test::expectSameVisibilityAcrossPrograms(paper.visibility, fast.visibility, [&] { return fast.visibility; });
  EXPECT_TRUE(timed(paper, StencilCounting::kPass));
  EXPECT_FALSE(timed(paper, "volumes"));
  EXPECT_TRUE(timed(fast, "volumes"));
  EXPECT_FALSE(timed(fast, StencilCounting::kPass));
}

class StencilVolumes : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_F(StencilVolumes, EveryBundledSceneMatchesTheFastPathAtTwoSizes) {
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(TESTBED_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".json") continue;
    const Scene scene = test::bundledScene(entry.path().stem().string());
    for (const glm::ivec2 size : {glm::ivec2(320, 180), glm::ivec2(203, 117)}) expectPathsAgree(scene, size);
    ++scenes;
  }
  EXPECT_GE(scenes, 5);
}

TEST_F(StencilVolumes, HardCasesMatchTheFastPath) {
  // Open meshes (volumes for both facings), a directional light, an occluder the camera's
  // near plane clips.
  expectPathsAgree(test::openMeshesScene(), {320, 180});
  expectPathsAgree(test::boxOverPlane(test::directional({0.4f, -1, 0.2f})), {320, 180});
  expectPathsAgree(test::nearPlaneScene(), {320, 180});
}

TEST_F(StencilVolumes, AnEyeInsideAVolumeMatchesWhereDepthPassFails) {
  // The camera under the slab is inside its volume: depth-pass counting misses the slab's
  // volume there, depth-fail (both paths here) does not.
  const Scene scene = test::cameraInVolumeScene();
  for (const glm::ivec2 size : {glm::ivec2(320, 180), glm::ivec2(203, 117)}) {
    expectPathsAgree(scene, size);
    const TechniqueRun paper = render(scene, size, TechniquePath::Paper);
    const TechniqueRun depthPass = render(scene, size, TechniquePath::Fast, depthPassGroundTruth());
    EXPECT_GT(test::differingPixels(paper.visibility, depthPass.visibility), 0);
  }
}

TEST_F(StencilVolumes, TheAreaReferenceMatchesTheFastPath) {
  // Per-sample stencil clears and the weights' blended sum.
  Scene scene = test::bundledScene("wall");
  RenderSettings settings = test::renderSettings({160, 90}, 64);
  const auto area = [&](TechniquePath path) {
    settings.path = path;
    FrameRunner runner(scene, settings);
    const auto& reference = areaLightReference();
    return runner.run(reference, resolveParameters("area", reference.info->parameters, {{"area_samples", "8"}}));
  };
  const TechniqueRun paper = area(TechniquePath::Paper), fast = area(TechniquePath::Fast);
  test::expectSameVisibilityAcrossPrograms(paper.visibility, fast.visibility, [&] { return fast.visibility; });
  int penumbra = 0;
  for (float v : fast.visibility.pixels) penumbra += v > 0.0f && v < 1.0f;
  EXPECT_GT(penumbra, 0);
}

TEST_F(StencilVolumes, RendersWithinItsDeclarationOnBothPaths) {
  const TechniqueInfo& info = *shadowVolumeGroundTruth().info;
  EXPECT_EQ(declarationProblem(info.passes, info.resources), "");
  const glm::ivec2 size{64, 36};
  const std::uint64_t screenBytes = std::uint64_t(size.x) * size.y * 4;  // R32F, DEPTH24_STENCIL8
  for (const TechniquePath path : {TechniquePath::Paper, TechniquePath::Fast}) {
    SCOPED_TRACE(std::string(pathName(path)) + " path");
    const TechniqueRun run = render(test::bundledScene("fence"), size, path);
    const std::vector<std::string> declared = passNamesOn(info.passes, path);
    for (const auto& pass : run.times.order)
      EXPECT_NE(std::find(declared.begin(), declared.end(), pass), declared.end()) << pass;
    // The memory block is the run's whole memory: the volumes' buffer and the count.
    ASSERT_EQ(run.memory.size(), 2u);
    std::uint64_t total = 0;
    for (const auto& m : run.memory) total += m.bytes;
    EXPECT_EQ(total, run.memoryBytes);
    const auto find = [&](const std::string& name) {
      return std::find_if(run.memory.begin(), run.memory.end(), [&](const auto& m) { return m.name == name; });
    };
    ASSERT_NE(find("volume-geometry"), run.memory.end());
    EXPECT_EQ(find("volume-geometry")->format, "buffer");
    EXPECT_GT(find("volume-geometry")->bytes, 0u);
    const std::string count = path == TechniquePath::Paper ? "stencil" : "volume-counts";
    ASSERT_NE(find(count), run.memory.end());
    EXPECT_EQ(find(count)->format, path == TechniquePath::Paper ? "DEPTH24_STENCIL8" : "R32F");
    EXPECT_EQ(find(count)->role, path == TechniquePath::Paper ? ResourceRole::Paper : ResourceRole::Device);
    EXPECT_EQ(find(count)->bytes, screenBytes);
  }
}

}  // namespace
}  // namespace testbed
