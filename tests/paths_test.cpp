// The two paths (docs/paths.md) give one output: every technique whose paper structure
// differs from its fast one renders the same visibility on both — bit for bit on llvmpipe,
// within test::expectSameVisibilityAcrossPrograms's bounds elsewhere — on every bundled
// scene, at two shadow-map sizes, with default and with other parameters. And the paper
// path holds only the papers' resources: the revectorization family the shadow map alone,
// as sm (GI 2016 §4.3), smsr-2pass also its discontinuity map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "testbed/harness/frame_runner.h"
#include "tests/gl_fixture.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

using Assignments = std::map<std::string, std::string>;

struct Case {
  std::string id;
  Assignments set;
};

// Defaults, then parameters away from them (other visibility functions, walk lengths,
// kernels, epsilon and bias).
const std::vector<Case> kCases = {
    {"smsr", {}},
    {"smsr", {{"visibility", "improved"}, {"max_search", "8"}, {"epsilon", "2.5e-06"}}},
    {"rsmss", {}},
    {"rsmss", {{"max_search", "5"}, {"bias", "0.0005"}}},
    {"rpcf-smsr", {}},
    {"rpcf-smsr", {{"kernel", "5"}, {"visibility", "improved"}}},
    {"rpcf-rsmss", {}},
    {"rpcf-rsmss", {{"kernel", "7"}, {"max_search", "12"}}},
    {"smsr-2pass", {}},
    {"smsr-2pass", {{"max_search", "6"}, {"epsilon", "0"}}},
    {"silhouette-map", {}},
    {"silhouette-map", {{"occlusion_bias", "0.01"}}},
    {"edtsm", {}},
    {"edtsm-star", {{"penumbra", "2"}, {"max_search", "8"}}},
};

std::string label(const Case& c) {
  std::string text = c.id;
  for (const auto& [name, value] : c.set) text += " " + name + "=" + value;
  return text;
}


RenderSettings onPath(glm::ivec2 size, int mapSize, TechniquePath path) {
  RenderSettings settings = test::renderSettings(size, mapSize);
  settings.path = path;
  return settings;
}

std::vector<std::string> bundledSceneNames() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(TESTBED_SOURCE_DIR) / "scenes"))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Paths, BothPathsGiveTheSameVisibility) {
  test::sharedContext();
  const std::vector<std::string> scenes = bundledSceneNames();
  ASSERT_GE(scenes.size(), 5u);
  for (const std::string& name : scenes)
    for (const int mapSize : {256, 512}) {
      SCOPED_TRACE(name + " " + std::to_string(mapSize));
      const Scene scene = test::bundledScene(name);
      FrameRunner paper(scene, onPath({320, 180}, mapSize, TechniquePath::Paper));
      FrameRunner fast(scene, onPath({320, 180}, mapSize, TechniquePath::Fast));
      ASSERT_EQ(paper.path(), TechniquePath::Paper);
      ASSERT_EQ(fast.path(), TechniquePath::Fast);
      for (const Case& c : kCases) {
        SCOPED_TRACE(label(c));
        const ImageF a = test::runTechnique(paper, c.id, c.set).visibility;
        const ImageF b = test::runTechnique(fast, c.id, c.set).visibility;
        test::expectSameVisibilityAcrossPrograms(a, b, [&] { return test::groundTruthVisibility(fast); });
        // Not a vacuous match: the frame has receivers in shadow and in light.
        const test::Receivers receivers = test::receiversOf(a);
        EXPECT_GT(receivers.dark, 0);
        EXPECT_LT(receivers.dark, receivers.count);
      }
    }
}

// The bound two programs are held to off llvmpipe: an edge that moves by a pixel passes, a
// receiver far from every boundary that changes, or a receiver one program drops, fails.
TEST(Paths, OffLlvmpipeAnEdgeMayMoveButNoSurfaceChanges) {
  ImageF truth;
  truth.width = 16;
  truth.height = 8;
  truth.channels = 1;
  truth.pixels.assign(16 * 8, 1.0f);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) truth.pixels[y * 16 + x] = 0.0f;  // shadow on the left half
  ImageF movedEdge = truth;
  for (int y = 0; y < 8; ++y) movedEdge.pixels[y * 16 + 8] = 0.0f;
  EXPECT_EQ(test::differenceBeyondArithmetic(truth, movedEdge, truth), "");
  ImageF farChange = truth;
  farChange.pixels[4 * 16 + 14] = 0.5f;
  EXPECT_NE(test::differenceBeyondArithmetic(truth, farChange, truth).find("1 receivers far"), std::string::npos);
  ImageF dropped = truth;
  dropped.pixels[0] = std::nanf("");
  EXPECT_NE(test::differenceBeyondArithmetic(truth, dropped, truth).find("receiver of one program"), std::string::npos);
}

using Resources = std::vector<GpuMemoryLedger::Resource>;

std::vector<std::string> namesOf(const Resources& resources, ResourceRole role) {
  std::vector<std::string> names;
  for (const auto& r : resources)
    if (r.role == role) names.push_back(r.name);
  return names;
}

// GI 2016 §4.3: revectorization needs the shadow map alone. On the paper path the family
// costs sm's memory exactly and holds only resources its papers define; the fast path's
// devices are booked as such. Pass lists follow the papers' steps.
TEST(Paths, PaperPathHoldsOnlyThePapersResources) {
  test::sharedContext();
  const Scene scene = test::bundledScene("fence");
  const glm::ivec2 size{320, 180};
  FrameRunner paper(scene, onPath(size, 512, TechniquePath::Paper));
  FrameRunner fast(scene, onPath(size, 512, TechniquePath::Fast));
  const TechniqueRun sm = test::runTechnique(paper, "sm");
  EXPECT_EQ(sm.memory, (Resources{{"shadow-map", "DEPTH_COMPONENT16", ResourceRole::Paper, 512u * 512u * 2u}}));
  EXPECT_EQ(test::runTechnique(fast, "sm").memory, sm.memory);
  for (const std::string id : {"smsr", "rsmss", "rpcf-smsr", "rpcf-rsmss"}) {
    SCOPED_TRACE(id);
    const TechniqueRun p = test::runTechnique(paper, id), f = test::runTechnique(fast, id);
    EXPECT_EQ(p.memoryBytes, sm.memoryBytes);
    EXPECT_EQ(p.memory, sm.memory);
    EXPECT_EQ(p.times.order, (std::vector<std::string>{"shadow-map", "revectorize"}));
    const bool rpcf = id.starts_with("rpcf");
    EXPECT_EQ(namesOf(f.memory, ResourceRole::Device),
              rpcf ? (std::vector<std::string>{"depth-image", "edge-marks", "rpcf-tile-bounds"})
                   : (std::vector<std::string>{"depth-image", "edge-marks"}));
    EXPECT_EQ(namesOf(f.memory, ResourceRole::Paper), std::vector<std::string>{"shadow-map"});
    EXPECT_EQ(f.times.order,
              rpcf ? (std::vector<std::string>{"shadow-map", "tile-bounds", "depth-copy", "classify", "revectorize"})
                   : (std::vector<std::string>{"shadow-map", "depth-copy", "classify", "revectorize"}));
  }
  // smsr-2pass: plus its screen-size RGBA8 discontinuity map, and on neither path a depth
  // image (its programs read none).
  const TechniqueRun p = test::runTechnique(paper, "smsr-2pass"), f = test::runTechnique(fast, "smsr-2pass");
  EXPECT_EQ(p.memory, (Resources{{"discontinuity-map", "RGBA8", ResourceRole::Paper, 320u * 180u * 4u}, sm.memory[0]}));
  EXPECT_EQ(p.times.order, (std::vector<std::string>{"shadow-map", "discontinuity", "revectorize"}));
  EXPECT_EQ(namesOf(f.memory, ResourceRole::Device), std::vector<std::string>{"edge-marks"});
  EXPECT_EQ(f.times.order, (std::vector<std::string>{"shadow-map", "discontinuity", "classify", "revectorize"}));
}

}  // namespace
}  // namespace testbed
