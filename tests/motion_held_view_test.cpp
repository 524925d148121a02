// Temporal figures at a held camera, end to end through the binary (docs/motion.md
// "Temporal metrics"): frame t is compared with frame t-1's scene seen through frame t's
// camera. A camera that moves alone then changes nothing, for every technique; a light
// that moves gives the change a viewer sees at each surface point, whatever the camera's
// speed. The animations are written here, not bundled.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace testbed::test;

json readJson(const fs::path& file) { return json::parse(readFile(file)); }

// The fence under a spot light: many thin edges, each a shadow boundary that aliases.
json fenceScene() { return readJson(fs::path(TESTBED_SOURCE_DIR) / "scenes" / "fence.json"); }

// The camera orbits the fence's centre at its file distance and height, `degrees` in all
// over `frames` frames (one key per frame: a constant distance, so the receivers keep
// their pixel density at every speed).
json orbit(int frames, double degrees) {
  json keys = json::array();
  for (int k = 0; k < frames; ++k) {
    const double a = degrees * std::numbers::pi / 180 * k / std::max(frames - 1, 1);
    keys.push_back({{"frame", k}, {"eye", {-46 * std::sin(a), 28, 4 - 46 * std::cos(a)}}, {"target", {0, 0, 4}}});
  }
  return keys;
}

// The spot light's eye slides 3 units sideways over the frames: every fence shadow moves.
json slidingLight(int frames) {
  return json::array({{{"frame", 0}, {"eye", {15, 30, 55}}}, {{"frame", frames - 1}, {"eye", {18, 30, 55}}}});
}

json runCompare(const TempDir& tmp, const std::string& name, const json& scene, const std::string& techniques,
                const std::vector<std::string>& size) {
  const fs::path file = writeFile(tmp / (name + ".json"), scene.dump());
  const fs::path out = tmp / name;
  const RunResult run = runTestbed(with({"compare", "--scene", file.string(), "--techniques", techniques, "--frames",
                                         "all", "--no-plot", "--out", out.string()},
                                        size));
  EXPECT_EQ(run.exitCode, 0) << run.describe();
  json byId = json::object();
  if (run.exitCode != 0) return byId;
  for (const json& record : readJson(out / "sequence.json")) byId[record.at("technique").get<std::string>()] = record;
  return byId;
}

// Translating and turning the camera while light and objects stay: the held view of each
// frame is the frame itself, so every registered technique (and the ground truth) reads 0
// on all three figures, exactly, although each frame needed its held render. Under the
// reprojected definition this read sm crawl > 0 (pixel centres resampling fixed edges).
TEST(MotionHeldView, CameraOnlyAnimationReadsZeroForEveryTechnique) {
  TempDir tmp;
  json scene = fenceScene();
  scene["animation"] = {{"frames", 3},
                        {"camera", {{{"frame", 0}, {"eye", {0, 28, -42}}, {"target", {0, 0, 4}}},
                                    {{"frame", 2}, {"eye", {9, 24, -36}}, {"target", {3, 1, 8}}}}}};
  const json records = runCompare(tmp, "camera_only", scene, "all", {"--size", "96x64", "--shadow-map", "128"});
  ASSERT_GT(records.size(), 10u) << "every registered technique";
  for (const auto& [id, record] : records.items()) {
    SCOPED_TRACE(id);
    const json& t = record.at("temporal");
    EXPECT_EQ(t.at("flicker").get<double>(), 0.0);
    EXPECT_EQ(t.at("crawl_pct").get<double>(), 0.0);
    EXPECT_EQ(t.at("crawl_missed_pct").get<double>(), 0.0);
    EXPECT_GT(t.at("stable_pairs").get<double>(), 0.0);
    EXPECT_EQ(t.at("moved_pixels").get<double>(), 0.0) << "nothing moved in world space";
    EXPECT_EQ(t.at("held_renders").get<int>(), 2) << "the camera moved at both frames";
  }
}

// A light that moves: the ground truth against itself reads 0, and sm's texel-sized edge
// steps crawl where the true shadow edge does not cross a pixel's threshold.
TEST(MotionHeldView, MovingLightGroundTruthZeroAndShadowMapCrawls) {
  TempDir tmp;
  json scene = fenceScene();
  scene["animation"] = {{"frames", 4}, {"light", slidingLight(4)}};
  const json records = runCompare(tmp, "light", scene, "sm", {"--size", "160x120", "--shadow-map", "256"});
  ASSERT_TRUE(records.contains("sm") && records.contains("groundtruth"));
  const json& truth = records.at("groundtruth").at("temporal");
  EXPECT_EQ(truth.at("flicker").get<double>(), 0.0);
  EXPECT_EQ(truth.at("crawl_pct").get<double>(), 0.0);
  EXPECT_EQ(truth.at("crawl_missed_pct").get<double>(), 0.0);
  const json& sm = records.at("sm").at("temporal");
  EXPECT_GT(sm.at("crawl_pct").get<double>(), 0.0);
  EXPECT_GT(sm.at("flicker").get<double>(), 0.0);
  EXPECT_EQ(sm.at("held_renders").get<int>(), 0) << "a still camera reuses the previous frame";
  EXPECT_EQ(sm.at("moved_pixels").get<double>(), 0.0);
}

// One light path, the camera orbiting at two speeds (2° and 20° over the run): the
// figures describe the light's motion, not the camera's, so they agree within
// kSpeedTolerance relative (what differs is only which pixels sample the receivers;
// measured on llvmpipe: flicker 3 %, crawl 3 %, crawl missed 9 % apart). A held view
// whose G-buffer kept the previous camera fails it by far (flicker 0.028 apart on 0.040, 69 %).
TEST(MotionHeldView, MovingLightFiguresDoNotDependOnCameraSpeed) {
  constexpr int kFrames = 6;
  constexpr double kSpeedTolerance = 0.15;
  TempDir tmp;
  const std::vector<std::string> size = {"--size", "160x120", "--shadow-map", "256"};
  json figures[2];
  const double degrees[2] = {2, 20};
  for (int i = 0; i < 2; ++i) {
    json scene = fenceScene();
    scene["animation"] = {{"frames", kFrames}, {"light", slidingLight(kFrames)}, {"camera", orbit(kFrames, degrees[i])}};
    const json records = runCompare(tmp, "speed" + std::to_string(i), scene, "sm", size);
    ASSERT_TRUE(records.contains("sm"));
    figures[i] = records.at("sm").at("temporal");
    EXPECT_EQ(figures[i].at("held_renders").get<int>(), kFrames - 1);
  }
  for (const char* name : {"flicker", "crawl_pct", "crawl_missed_pct"}) {
    SCOPED_TRACE(name);
    const double slow = figures[0].at(name).get<double>(), fast = figures[1].at(name).get<double>();
    EXPECT_GT(slow, 0.0) << "the light moves: the figures are not trivially equal";
    EXPECT_LE(std::abs(fast - slow), kSpeedTolerance * slow) << "slow " << slow << ", fast " << fast;
  }
}

}  // namespace
