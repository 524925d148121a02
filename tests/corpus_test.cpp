// `testbed corpus` end to end: two runs are byte-identical, bad options are refused with
// one line naming the option and nothing written, and the generated scenes (from the
// installed assets and assimp-testmodels) load and mostly show a shadow boundary.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "testbed/metrics/metrics.h"
#include "testbed/scene/scene.h"
#include "tests/cli_helpers.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

TEST(CorpusCommand, TwoRunsAreByteIdentical) {
  test::TempDir dir;
  for (const char* out : {"a", "b"}) {
    const auto run = test::runTestbed({"corpus", "--seed", "1234", "--count", "5", "--out", (dir / out).string()});
    ASSERT_EQ(run.exitCode, 0) << run.describe();
  }
  const auto names = test::filesIn(dir / "a");
  ASSERT_EQ(names.size(), 6u);  // five scenes and the manifest
  EXPECT_EQ(names, test::filesIn(dir / "b"));
  for (const auto& name : names) EXPECT_EQ(test::readFile(dir / "a" / name), test::readFile(dir / "b" / name)) << name;
}

// The manifest names the asset folder and its meshes "assets/…", not where the folder is
// on this machine: the same meshes in two places give the same manifest.
TEST(CorpusCommand, ManifestNamesAssetsRelativeToTheAssetFolder) {
  test::TempDir dir;
  std::vector<std::string> manifests;
  for (const char* place : {"here", "there"}) {
    const std::filesystem::path assets = dir / place / "assets-copy";
    std::filesystem::create_directories(assets);
    for (const char* mesh : {"cow.off", "knot.off"}) std::filesystem::copy_file(assetDirectory() / mesh, assets / mesh);
    test::RunOptions options;
    options.env = {{"TESTBED_ASSET_DIR", assets.string()}};
    const auto run = test::runTestbed({"corpus", "--seed", "5", "--count", "2", "--out", (dir / place / "out").string(),
                                       "--meshes", assets.string()},
                                      options);
    ASSERT_EQ(run.exitCode, 0) << run.describe();
    manifests.push_back(test::readFile(dir / place / "out" / "manifest.json"));
  }
  EXPECT_EQ(manifests[0], manifests[1]);
  const auto manifest = nlohmann::json::parse(manifests[0]);
  EXPECT_EQ(manifest["mesh_folders"], nlohmann::json::array({"assets"}));
  EXPECT_EQ(manifest["meshes"][0]["mesh"], "assets/cow.off");
  EXPECT_EQ(manifest["meshes"][1]["mesh"], "assets/knot.off");
  for (const auto& scene : manifest["scenes"]) EXPECT_TRUE(scene["mesh"].get<std::string>().starts_with("assets/"));
}

TEST(CorpusCommand, BadOptionsAreRefusedAndNothingIsWritten) {
  test::TempDir dir;
  test::writeFile(dir / "a-file", "x");
  const std::string out = (dir / "out").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--seed", "-1", "--count", "2", "--out", out}, "--seed"},
      {{"--seed", "abc", "--count", "2", "--out", out}, "--seed"},
      {{"--seed", "18446744073709551616", "--count", "2", "--out", out}, "--seed"},
      {{"--seed", "1", "--count", "0", "--out", out}, "--count"},
      {{"--seed", "1", "--count", "10001", "--out", out}, "--count"},
      {{"--seed", "1", "--count", "2.5", "--out", out}, "--count"},
      {{"--seed", "1", "--count", "2", "--out", (dir / "a-file").string()}, "--out"},
      {{"--seed", "1", "--count", "2", "--out", out, "--meshes", (dir / "none").string()}, "--meshes"},
      {{"--seed", "1", "--count", "2", "--out", out, "--meshes", dir.path().string()}, "--meshes"},
  };
  for (const auto& [args, option] : cases) {
    std::vector<std::string> words = {"corpus"};
    words.insert(words.end(), args.begin(), args.end());
    const auto run = test::runTestbed(words);
    EXPECT_TRUE(test::rejectedWithOneLine(run)) << run.describe();
    EXPECT_NE(run.err.find(option), std::string::npos) << run.describe();
    EXPECT_FALSE(std::filesystem::exists(out)) << run.describe();
  }
}

// Every scene of a 12-scene corpus loads and renders its ground truth; most have a shadow
// boundary in view (a low sun behind a wall can leave a close-up wholly in shadow).
TEST(CorpusCommand, GeneratedScenesLoadAndMostShowAShadowBoundary) {
  test::TempDir dir;
  const auto run = test::runTestbed({"corpus", "--seed", "2026", "--count", "12", "--out", dir.path().string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  test::sharedContext();
  int withBoundary = 0, total = 0;
  for (const auto& name : test::filesIn(dir.path())) {
    if (name == "manifest.json") continue;
    const Scene scene = loadScene(dir / name);
    FrameRunner runner(scene, test::renderSettings({320, 180}, 1024));
    const ImageF truth = test::groundTruthVisibility(runner);
    const ErrorMetrics self = computeErrorMetrics(truth, truth);
    std::cout << "[ corpus   ] " << name << ": " << self.receivers << " receivers, " << self.gtBoundaryPixels
              << " boundary pixels\n";
    ++total;
    withBoundary += self.gtBoundaryPixels > 0;
  }
  EXPECT_EQ(total, 12);
  EXPECT_GE(withBoundary, 10) << withBoundary << " of " << total << " scenes have a shadow boundary";
}

}  // namespace
}  // namespace testbed
