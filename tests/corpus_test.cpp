// `testbed corpus` end to end: two runs are byte-identical, bad options and hostile meshes
// are refused with one line naming the option and nothing written, and the generated
// scenes (from the installed assets and assimp-testmodels) load, render, and show what
// the manifest says their check render showed.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "testbed/metrics/metrics.h"
#include "testbed/scene/scene.h"
#include "tests/cli_helpers.h"
#include "tests/gl_fixture.h"
#include "tests/mesh_fixtures.h"

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
      // Sizes the testbed would not render at, and a map so coarse for the image that a
      // close-up would stand beyond the camera's far plane.
      {{"--seed", "1", "--count", "2", "--out", out, "--size", "0x0"}, "--size"},
      {{"--seed", "1", "--count", "2", "--out", out, "--size", "-640x-360"}, "--size"},
      {{"--seed", "1", "--count", "2", "--out", out, "--size", "640x-360"}, "--size"},
      {{"--seed", "1", "--count", "2", "--out", out, "--size", "1280x100000"}, "--size"},
      {{"--seed", "1", "--count", "2", "--out", out, "--size", "8192x1"}, "--size"},
      {{"--seed", "1", "--count", "2", "--out", out, "--size", "100x401"}, "--size"},
      {{"--seed", "1", "--count", "2", "--out", out, "--shadow-map", "0"}, "--shadow-map"},
      {{"--seed", "1", "--count", "2", "--out", out, "--shadow-map", "-1024"}, "--shadow-map"},
      {{"--seed", "1", "--count", "2", "--out", out, "--shadow-map", "16"}, "--shadow-map"},
      {{"--seed", "1", "--count", "2", "--out", out, "--size", "2048x2048"}, "--shadow-map"},
      {{"--seed", "1", "--count", "2", "--out", out, "--backend", "nosuch"}, "nosuch"},
      {{"--seed", "1", "--count", "2", "--out", out, "--kind", "indoor"}, "--kind"},
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

// Meshes a folder may hold that no scene file can use: coordinates of 1e-40 (fitted to a
// scene's size they overflow float), a name that is not UTF-8 (JSON cannot hold it). Alone
// in --meshes they leave no usable mesh: one line naming --meshes, nothing written.
// Beside a good mesh they are skipped with their reason, and a 250-byte name makes a scene
// file name short enough to write.
TEST(CorpusCommand, HostileMeshesAreSkippedWithTheirReason) {
  test::TempDir dir;
  const std::string longName = std::string(246, 'm') + ".off", notUtf8 = "bad-\xff\xfe.off";
  test::writeFile(dir / "tiny/tiny.off", test::lumpySphereOff(1e-40));
  test::writeFile(dir / "named" / notUtf8, test::lumpySphereOff());
  for (const auto& [folder, line] : {std::pair{"tiny", "--meshes: no usable"}, {"named", "--meshes: no usable"}}) {
    const auto run = test::runTestbed({"corpus", "--seed", "1", "--count", "2", "--out", (dir / "out").string(),
                                       "--meshes", (dir / folder).string()});
    EXPECT_TRUE(test::rejectedWithOneLine(run)) << run.describe();
    EXPECT_NE(run.err.find(line), std::string::npos) << run.describe();
    EXPECT_FALSE(std::filesystem::exists(dir / "out")) << run.describe();
  }
  const auto mixed = dir / "mixed";
  test::writeFile(mixed / "tiny.off", test::lumpySphereOff(1e-40));
  test::writeFile(mixed / notUtf8, test::lumpySphereOff());
  test::writeFile(mixed / longName, test::lumpySphereOff());
  const auto run = test::runTestbed(
      {"corpus", "--seed", "3", "--count", "2", "--out", (dir / "out").string(), "--meshes", mixed.string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const auto manifest = nlohmann::json::parse(test::readFile(dir / "out" / "manifest.json"));
  ASSERT_EQ(manifest["skipped"].size(), 2u) << manifest["skipped"].dump(2);
  EXPECT_EQ(manifest["skipped"][0]["mesh"], (mixed / "bad-\uFFFD\uFFFD.off").string());
  EXPECT_NE(manifest["skipped"][0]["why"].get<std::string>().find("not UTF-8"), std::string::npos);
  EXPECT_NE(manifest["skipped"][1]["why"].get<std::string>().find("not finite"), std::string::npos);
  test::sharedContext();
  for (const auto& scene : manifest["scenes"]) {
    const std::string file = scene["file"];
    EXPECT_LT(file.size(), 64u) << file;
    EXPECT_EQ(loadScene(dir / "out" / file).objects.size() >= 2, true) << file;
  }
}

// Every scene of a 12-scene corpus loads and renders its ground truth; at the check size
// it shows what the manifest recorded (the admission: a boundary of at least 40 pixels,
// lit and shadowed receivers), and at twice that size it still has a boundary.
TEST(CorpusCommand, GeneratedScenesShowTheShadowBoundaryTheManifestRecords) {
  test::TempDir dir;
  const auto run = test::runTestbed({"corpus", "--seed", "2026", "--count", "12", "--out", dir.path().string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const auto manifest = nlohmann::json::parse(test::readFile(dir / "manifest.json"));
  ASSERT_EQ(manifest["scenes"].size(), 12u);
  for (const auto& mesh : manifest["meshes"]) {
    EXPECT_GE(mesh["triangles"].get<int>(), 200) << mesh.dump();
    EXPECT_EQ(mesh["mesh"].get<std::string>().find("/invalid/"), std::string::npos) << mesh.dump();
  }
  test::sharedContext();
  for (const auto& entry : manifest["scenes"]) {
    SCOPED_TRACE(entry.dump());
    const Scene scene = loadScene(dir / entry["file"].get<std::string>());
    for (const glm::ivec2 size : {glm::ivec2(160, 90), glm::ivec2(320, 180)}) {
      FrameRunner runner(scene, test::renderSettings(size, 1024));
      const ImageF truth = test::groundTruthVisibility(runner);
      const ErrorMetrics self = computeErrorMetrics(truth, truth);
      std::cout << "[ corpus   ] " << scene.name << " at " << size.x << "x" << size.y << ": " << self.receivers
                << " receivers, " << self.gtBoundaryPixels << " boundary pixels\n";
      if (size.x == 160) {
        EXPECT_EQ(self.gtBoundaryPixels, entry["check"]["boundary_px"].get<int>());
        EXPECT_EQ(self.gtLitReceivers, entry["check"]["lit"].get<int>());
        EXPECT_EQ(self.gtShadowReceivers, entry["check"]["shadowed"].get<int>());
        EXPECT_GE(self.gtBoundaryPixels, 40);
        EXPECT_GE(self.gtLitReceivers, 0.02 * self.receivers);
        EXPECT_GE(self.gtShadowReceivers, 0.02 * self.receivers);
      } else {
        EXPECT_GT(self.gtBoundaryPixels, 40);
      }
    }
  }
}

// --kind outdoor: the same seed gives the same bytes; every scene is a large ground under a
// low sun seen from near the ground, with casters from near to far ahead of the camera,
// sized with their distance; its check render admits it as the standard family's are; a
// walking scene moves the camera forward and nothing else.
TEST(CorpusCommand, OutdoorScenesStretchOneMapFromNearToFar) {
  test::TempDir dir;
  for (const char* out : {"a", "b"}) {
    const auto run = test::runTestbed({"corpus", "--kind", "outdoor", "--seed", "11", "--count", "6", "--out",
                                       (dir / out).string()});
    ASSERT_EQ(run.exitCode, 0) << run.describe();
  }
  for (const auto& name : test::filesIn(dir / "a"))
    EXPECT_EQ(test::readFile(dir / "a" / name), test::readFile(dir / "b" / name)) << name;
  const auto manifest = nlohmann::json::parse(test::readFile(dir / "a" / "manifest.json"));
  EXPECT_EQ(manifest["kind"], "outdoor");
  ASSERT_EQ(manifest["scenes"].size(), 6u);
  int walking = 0;
  for (const auto& entry : manifest["scenes"]) {
    SCOPED_TRACE(entry.dump());
    const Scene scene = loadScene(dir / "a" / entry["file"].get<std::string>());
    EXPECT_EQ(scene.light.type, LightType::Directional);
    const double elevation = glm::degrees(std::asin(-glm::normalize(scene.light.direction).y));
    EXPECT_GE(elevation, 12 - 1e-3);
    EXPECT_LE(elevation, 40 + 1e-3);
    EXPECT_LT(scene.camera.eye.y, 8.01f);
    EXPECT_GE(entry["check"]["shadowed"].get<int>(), 0.02 * entry["check"]["receivers"].get<int>());
    double previous = 0;
    for (const auto& caster : entry["casters"]) {
      const double distance = caster["distance"].get<double>(), size = caster["size"].get<double>();
      EXPECT_GE(distance, previous);
      EXPECT_GE(distance, 6 - 1e-3);
      EXPECT_LE(distance, 300 + 1e-3);
      EXPECT_NEAR(size / distance, 0.175, 0.075 + 1e-3);
      previous = distance;
    }
    EXPECT_GE(entry["casters"].size(), 4u);
    if (!entry["walk"].is_null()) {
      ++walking;
      ASSERT_NE(scene.animation, nullptr);
      const nlohmann::json file = nlohmann::json::parse(test::readFile(dir / "a" / entry["file"].get<std::string>()));
      EXPECT_FALSE(file["animation"].contains("light"));
      EXPECT_FALSE(file["animation"].contains("objects"));
      EXPECT_EQ(file["animation"]["camera"].size(), 2u);
    }
  }
  EXPECT_GT(walking, 0);
  EXPECT_LT(walking, 6);
}

}  // namespace
}  // namespace testbed
