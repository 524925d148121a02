// `testbed view` end to end: the real binary in a real window under Xvfb (its own server
// on a free display, started and stopped by each test). The viewer shares the frame
// harness with `render`, so its screenshots must be `render`'s T.png, byte for byte.
// Tests that need no window run without a display: bad input must fail before one opens.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/io/image_io.h"
#include "testbed/metrics/metrics.h"
#include "testbed/scene/animation.h"
#include "testbed/technique/registry.h"
#include "testbed/viewer/panel.h"
#include "testbed/viewer/viewer.h"
#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace testbed::test;

constexpr const char* kXvfb = "/usr/bin/Xvfb";

// An Xvfb server on a display it picks itself (-displayfd), stopped by the destructor.
class Xvfb {
 public:
  Xvfb() {
    int fds[2];
    if (::pipe(fds) != 0) return;
    const std::string fd = std::to_string(fds[1]);
    std::vector<std::string> args = {kXvfb, "-displayfd", fd, "-screen", "0", "2560x1440x24", "-nolisten", "tcp"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);  // its chatter
    const bool spawned = posix_spawn(&pid_, kXvfb, &actions, nullptr, argv.data(), environ) == 0;
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (!spawned) pid_ = -1;
    // It writes the display number once it accepts connections.
    pollfd ready{fds[0], POLLIN, 0};
    std::string number;
    char c;
    while (spawned && ::poll(&ready, 1, 20000) > 0 && ::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (!number.empty()) display_ = ":" + number;
  }
  ~Xvfb() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  Xvfb(const Xvfb&) = delete;
  Xvfb& operator=(const Xvfb&) = delete;
  const std::string& display() const { return display_; }

 private:
  pid_t pid_ = -1;
  std::string display_;
};

// Runs the testbed binary with `display` as DISPLAY (empty: none at all).
RunResult testbed(const std::vector<std::string>& args, const std::string& display = {}) {
  RunOptions options{.timeoutSeconds = 180};
  if (display.empty())
    options.unset = {"DISPLAY"};
  else
    options.env = {{"DISPLAY", display}};
  return runTestbed(args, options);
}

fs::path scene(const std::string& name) { return fs::path(TESTBED_SOURCE_DIR) / "scenes" / name; }

// Small enough for llvmpipe to run a dozen techniques in seconds.
const std::vector<std::string> kCommon = {"--size", "320x180", "--shadow-map", "512"};

// Largest difference of two images in 8-bit steps; 256 when their shapes differ.
int maxStepDifference(const testbed::ImageF& a, const testbed::ImageF& b) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) return 256;
  int worst = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    worst = std::max(worst, int(std::lround(std::abs(a.pixels[i] - b.pixels[i]) * 255.0f)));
  return worst;
}

// Filtered techniques may round differently in the last bit of a filter weight: allowed
// one 8-bit step. Hard techniques must match exactly.
int toleranceFor(const std::string& id) {
  return testbed::findTechnique(id).info->output == testbed::OutputKind::Hard ? 0 : 1;
}

class ViewerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(kXvfb)) GTEST_SKIP() << kXvfb << " is not installed (Debian package xvfb)";
    xvfb_ = std::make_unique<Xvfb>();
    ASSERT_FALSE(xvfb_->display().empty()) << "Xvfb did not start";
  }
  void TearDown() override { xvfb_.reset(); }

  RunResult view(const std::vector<std::string>& args) { return testbed(with({"view"}, args), xvfb_->display()); }

  // `render` (default backend, osmesa) of `id` on `sceneFile`; returns its T.png.
  testbed::ImageF render(const fs::path& sceneFile, const std::string& id, const std::vector<std::string>& extra = {}) {
    const fs::path out = dir_ / ("render-" + std::to_string(renders_++));
    const RunResult run = testbed(with(with({"render", "--scene", sceneFile.string(), "--technique", id, "--out", out.string()},
                                      kCommon),
                                 extra));
    EXPECT_EQ(run.exitCode, 0) << run.err;
    return testbed::readImage(out / (id + ".png"));
  }

  fs::path writeScript(const std::string& text) { return writeFile(dir_ / "script.txt", text); }

  std::unique_ptr<Xvfb> xvfb_;
  TempDir dir_{"testbed-viewer"};
  int renders_ = 0;
};

TEST_F(ViewerTest, FramesScreenshotEqualsRenderForAHardAndAFilteredTechnique) {
  for (const auto& [id, set] : std::vector<std::pair<std::string, std::string>>{{"sm", "bias=0"}, {"pcf", "kernel=5"}}) {
    const fs::path shot = dir_ / (id + "-view.png");
    const RunResult run = view(with({"--scene", scene("wall.json").string(), "--technique", id, "--set", set, "--frames", "3",
                               "--screenshot", shot.string()},
                              kCommon));
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_LE(maxStepDifference(testbed::readImage(shot), render(scene("wall.json"), id, {"--set", set})),
              toleranceFor(id))
        << id;
  }
}

// One viewer session walks through every registered technique; each screenshot is the
// T.png that `compare` (the same harness, every technique) writes for it.
TEST_F(ViewerTest, ScriptVisitingEveryTechniqueGivesCompareImages) {
  std::string script;
  for (const auto& t : testbed::registeredTechniques())
    script += "technique " + t.info->id + "\nscreenshot " + (dir_ / ("view-" + t.info->id + ".png")).string() + "\n";
  script += "quit\n";
  const RunResult run = view(with({"--scene", scene("wall.json").string(), "--script", writeScript(script).string()}, kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const fs::path out = dir_ / "compare";
  const RunResult compare = testbed(with({"compare", "--scene", scene("wall.json").string(), "--out", out.string()}, kCommon));
  ASSERT_EQ(compare.exitCode, 0) << compare.err;
  for (const auto& t : testbed::registeredTechniques()) {
    const std::string& id = t.info->id;
    EXPECT_LE(maxStepDifference(testbed::readImage(dir_ / ("view-" + id + ".png")), testbed::readImage(out / (id + ".png"))),
              toleranceFor(id))
        << id;
  }
}

// Switching technique and parameters by script gives what `render --set` gives.
TEST_F(ViewerTest, ScriptSwitchingTechniqueAndParameterMatchesRender) {
  const fs::path a = dir_ / "a.png", b = dir_ / "b.png", c = dir_ / "c.png";
  const RunResult run = view(with({"--scene", scene("wall.json").string(), "--script",
                             writeScript("technique pcf\nset kernel=7\nset bilinear=true\nscreenshot " + a.string() +
                                         "\ntechnique evsm\nset moments=2\nframes 2\nscreenshot " + b.string() +
                                         "\ntechnique smsr\nset max_search=4\nscreenshot " + c.string() + "\nquit\n")
                                 .string()},
                            kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_LE(maxStepDifference(testbed::readImage(a),
                              render(scene("wall.json"), "pcf", {"--set", "kernel=7", "--set", "bilinear=true"})),
            1);
  EXPECT_LE(maxStepDifference(testbed::readImage(b), render(scene("wall.json"), "evsm", {"--set", "moments=2"})), 1);
  EXPECT_EQ(maxStepDifference(testbed::readImage(c), render(scene("wall.json"), "smsr", {"--set", "max_search=4"})), 0);
}

// Moving camera and light, then saving the scene: `render` of the saved scene is the view.
TEST_F(ViewerTest, SavedSceneRendersWhatTheMovedViewShows) {
  const fs::path shot = dir_ / "moved.png", saved = dir_ / "saved" / "moved.json";
  const RunResult run = view(with({"--scene", scene("wall.json").string(), "--script",
                             writeScript("orbit 25 10\nzoom 0.8\npan 10 -5\nlight 30 -5\nsave-scene " + saved.string() +
                                         "\nscreenshot " + shot.string() + "\nquit\n")
                                 .string()},
                            kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const testbed::ImageF moved = testbed::readImage(shot);
  EXPECT_EQ(maxStepDifference(moved, render(saved, "sm")), 0);
  EXPECT_GT(maxStepDifference(moved, render(scene("wall.json"), "sm")), 10) << "the view did not move";
}

// The error heat map and the metrics are compare's: same error block, and the heat map's
// pure red/blue pixels are exactly the mismatched receivers.
TEST_F(ViewerTest, ErrorModeAndMetricsAgreeWithCompare) {
  const fs::path heat = dir_ / "heat.png", metrics = dir_ / "metrics.json";
  const RunResult run = view(with({"--scene", scene("wall.json").string(), "--technique", "sm", "--script",
                             writeScript("mode error\nscreenshot " + heat.string() + "\nmetrics " + metrics.string() +
                                         "\nquit\n")
                                 .string()},
                            kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const fs::path out = dir_ / "compare";
  ASSERT_EQ(testbed(with({"compare", "--scene", scene("wall.json").string(), "--techniques", "sm", "--out", out.string()},
                         kCommon))
                .exitCode,
            0);
  std::ifstream viewRecord(metrics), compareRecord(out / "sm.json");
  const json fromView = json::parse(viewRecord), fromCompare = json::parse(compareRecord);
  EXPECT_EQ(fromView["error"], fromCompare["error"]);
  EXPECT_EQ(fromView["params"], fromCompare["params"]);
  EXPECT_EQ(fromView["technique"], "sm");

  const testbed::ImageF image = testbed::readImage(heat);
  const testbed::ImageF truth = testbed::readImage(out / "groundtruth.exr");
  int mismatched = 0, receivers = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (std::isnan(truth.at(x, y))) continue;
      ++receivers;
      const float r = image.at(x, y, 0), g = image.at(x, y, 1), b = image.at(x, y, 2);
      mismatched += g == 0 && ((r == 1 && b == 0) || (r == 0 && b == 1));
    }
  }
  ASSERT_GT(receivers, 0);
  EXPECT_NEAR(100.0 * mismatched / receivers, fromCompare["error"]["mismatch_pct"].get<double>(), 1e-9);
}

// soft-error mode is compare --reference soft's heat map: the same sm frame against the same
// area-light reference (64 samples, compare's default with --reference soft), recomputed here
// from compare's sm.exr and area.exr; one 8-bit step for the PNG's rounding. Its metrics
// (the panel's figures) are compare's soft ones, beside the hard ones.
TEST_F(ViewerTest, SoftErrorModeIsTheHeatMapAgainstTheAreaReference) {
  const fs::path heat = dir_ / "soft_heat.png", metrics = dir_ / "soft_metrics.json";
  const RunResult run = view(with({"--scene", scene("wall.json").string(), "--technique", "sm", "--script",
                                   writeScript("mode soft-error\nscreenshot " + heat.string() + "\nmetrics " +
                                               metrics.string() + "\nquit\n")
                                       .string()},
                                  kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const fs::path out = dir_ / "compare_soft";
  ASSERT_EQ(testbed(with({"compare", "--scene", scene("wall.json").string(), "--techniques", "sm", "--reference",
                          "soft", "--out", out.string()},
                         kCommon))
                .exitCode,
            0);
  const testbed::ImageF expected =
      testbed::softErrorHeatMap(testbed::readImage(out / "sm.exr"), testbed::readImage(out / "area.exr"));
  const testbed::ImageF shown = testbed::readImage(heat);
  EXPECT_LE(maxStepDifference(shown, expected), 1);
  // Not the hard heat map: sm's edge is red/blue there, but tinted by |v - ref| here.
  const testbed::ImageF hard = testbed::errorHeatMap(testbed::readImage(out / "sm.exr"),
                                                     testbed::readImage(out / "groundtruth.exr"));
  EXPECT_GT(maxStepDifference(shown, hard), 10);
  const json fromView = json::parse(readFile(metrics)), fromCompare = json::parse(readFile(out / "sm.json"));
  for (const char* name : {"soft_rmse", "soft_penumbra_mae", "soft_outside_mae", "soft_umbra_leak"}) {
    ASSERT_TRUE(fromView["error"][name].is_number()) << name << ": " << fromView["error"].dump();
    EXPECT_EQ(fromView["error"][name], fromCompare["error"][name]) << name;
  }
}

// The window: the panel at the left, the 3D view beside it showing the screenshot's bytes.
TEST_F(ViewerTest, WindowScreenshotShowsThePanelBesideTheExactView) {
  const fs::path shot = dir_ / "view.png", window = dir_ / "window.png";
  const RunResult run = view(with({"--scene", scene("wall.json").string(), "--technique", "smsr", "--frames", "4",
                             "--screenshot", shot.string(), "--window-screenshot", window.string()},
                            kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const testbed::ImageF view = testbed::readImage(shot), whole = testbed::readImage(window);
  const glm::ivec2 expected = testbed::viewer::windowSizeFor({320, 180});
  ASSERT_EQ(whole.width, expected.x);
  ASSERT_EQ(whole.height, expected.y);
  const int left = int(testbed::viewer::kPanelWidth);
  int different = 0;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x)
      for (int c = 0; c < 3; ++c) different += view.at(x, y, c) != whole.at(left + x, y, c);
  EXPECT_EQ(different, 0);
  // The panel is drawn: its area is not one flat colour.
  int panelColours = 0;
  for (int y = 0; y < whole.height; y += 7) panelColours += whole.at(40, y, 0) != whole.at(40, 0, 0);
  EXPECT_GT(panelColours, 3);
}

// `render --backend glfw` (a hidden window) runs the same rasterizer as OSMesa: same T.png.
TEST_F(ViewerTest, RenderOnTheGlfwBackendEqualsOsmesa) {
  const fs::path out = dir_ / "glfw";
  const RunResult run = testbed(with({"render", "--scene", scene("wall.json").string(), "--technique", "pcf", "--backend",
                                    "glfw", "--out", out.string()},
                                   kCommon),
                              xvfb_->display());
  ASSERT_EQ(run.exitCode, 0) << run.err;
  std::ifstream record(out / "pcf.json");
  EXPECT_EQ(json::parse(record)["backend"].get<std::string>().rfind("glfw: ", 0), 0u);
  EXPECT_EQ(maxStepDifference(testbed::readImage(out / "pcf.png"), render(scene("wall.json"), "pcf")), 0);
}

TEST_F(ViewerTest, PluginTechniquesAreShownLikeInTreeOnes) {
  const fs::path shot = dir_ / "plugin.png";
  const RunResult run = view(with({"--scene", scene("wall.json").string(), "--plugin", TESTBED_PLUGIN_EXAMPLE, "--technique",
                             "example-sm", "--frames", "2", "--screenshot", shot.string()},
                            kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_EQ(maxStepDifference(testbed::readImage(shot), render(scene("wall.json"), "sm")), 0);
}

// Playback (docs/viewer.md "Playing an animated scene"). The spinning occluder: only an
// object moves, so every figure depends on the object's upload and the caches keyed on it.
fs::path spinning() { return scene("motion/spinning_occluder.json"); }

// The animated scene frozen at `frame`: its animated objects' poses written as their
// `rotate`/`translate`/`scale` (floats printed exactly), the animation block dropped.
fs::path frozenAt(const fs::path& animatedFile, int frame, const fs::path& out) {
  const testbed::Scene scene = testbed::loadScene(animatedFile);
  json document = json::parse(readFile(animatedFile));
  for (const auto& track : scene.animation->objects) {
    const testbed::ObjectPose pose = testbed::poseAt(track, frame);
    auto vec = [](glm::vec3 v) { return json::array({double(v.x), double(v.y), double(v.z)}); };
    json& object = document["objects"][track.object];
    object["rotate"] = vec(pose.rotateDegrees);
    object["translate"] = vec(pose.translate);
    object["scale"] = vec(pose.scale);
  }
  document.erase("animation");
  return writeFile(out, document.dump());
}

// Seeking to frame k shows what `render` shows of frame k, and its error is the one
// `compare --frames k:k` records for that frame.
TEST_F(ViewerTest, SeekingShowsTheFrameThatRenderRendersAtThatFrame) {
  const int k = 29;
  const fs::path shot = dir_ / "frame.exr", metrics = dir_ / "frame.json";
  const RunResult run = view(with({"--scene", spinning().string(), "--technique", "sm", "--script",
                             writeScript("seek " + std::to_string(k) + "\nmode visibility\nscreenshot " + shot.string() +
                                         "\nmetrics " + metrics.string() + "\nquit\n")
                                 .string()},
                            kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const fs::path frozen = frozenAt(spinning(), k, dir_ / "frozen.json");
  render(frozen, "sm");
  const testbed::ImageF fromView = testbed::readImage(shot);
  const testbed::ImageF fromRender = testbed::readImage(dir_ / "render-0" / "sm.exr");
  ASSERT_EQ(fromView.width, fromRender.width);
  ASSERT_EQ(fromView.height, fromRender.height);
  int receivers = 0, different = 0;
  for (int y = 0; y < fromRender.height; ++y)
    for (int x = 0; x < fromRender.width; ++x) {
      if (std::isnan(fromRender.at(x, y))) continue;  // shown as the background grey
      ++receivers;
      different += fromView.at(x, y) != fromRender.at(x, y);
    }
  EXPECT_GT(receivers, 0);
  EXPECT_EQ(different, 0) << "of " << receivers << " receivers";

  const fs::path out = dir_ / "compare";
  const RunResult compare = testbed(with({"compare", "--scene", spinning().string(), "--techniques", "sm", "--frames",
                                          std::to_string(k) + ":" + std::to_string(k), "--no-plot", "--out", out.string()},
                                         kCommon));
  ASSERT_EQ(compare.exitCode, 0) << compare.err;
  const json record = json::parse(readFile(metrics));
  EXPECT_EQ(record.at("frame").get<int>(), k);
  EXPECT_EQ(record.at("error"), json::parse(readFile(out / "sm_frames.json"))[0].at("error"));
}

// Stepping frame by frame and playing both give the running flicker that `compare
// --frames 0:6` pools over the same frames (same code, same images: equal to 1e-12, the
// room left for summation order; the denominators exactly). `compare` runs on the
// viewer's rasterizer (--backend glfw), so filtered techniques match bit for bit too.
TEST_F(ViewerTest, RunningFlickerAfterSteppingOrPlayingIsTheSequenceRecords) {
  const fs::path sm = dir_ / "sm.json", pcf = dir_ / "pcf.json", back = dir_ / "back.json";
  const RunResult run = view(with({"--scene", spinning().string(), "--technique", "sm", "--script",
                             writeScript("step\nstep\nstep\nstep\nstep\nstep\nmetrics " + sm.string() +
                                         "\nstep -2\nmetrics " + back.string() +
                                         "\ntechnique pcf\nseek 0\nplay\nframes 5\npause\nmetrics " + pcf.string() +
                                         "\nquit\n")
                                 .string()},
                            kCommon));
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const fs::path out = dir_ / "compare";
  const RunResult compare = testbed(with({"compare", "--scene", spinning().string(), "--techniques", "sm,pcf",
                                          "--frames", "0:6", "--backend", "glfw", "--no-plot", "--out", out.string()},
                                         kCommon),
                                    xvfb_->display());
  ASSERT_EQ(compare.exitCode, 0) << compare.err;

  auto expectSameFigures = [&](const json& viewRecord, const std::string& id) {
    SCOPED_TRACE(id);
    ASSERT_EQ(viewRecord.at("frame").get<int>(), 6);
    const json& live = viewRecord.at("temporal");
    const json sequence = json::parse(readFile(out / (id + "_sequence.json"))).at("temporal");
    EXPECT_EQ(live.at("first_frame").get<int>(), 0);
    EXPECT_EQ(live.at("frame_pairs"), sequence.at("frame_pairs"));
    EXPECT_EQ(live.at("stable_pairs"), sequence.at("stable_pairs"));
    EXPECT_GT(sequence.at("flicker").get<double>(), 0.0) << "the occluder moves: its shadow's edges flicker";
    for (const char* figure : {"flicker", "crawl_pct", "crawl_missed_pct"})
      EXPECT_NEAR(live.at(figure).get<double>(), sequence.at(figure).get<double>(), 1e-12) << figure;
    EXPECT_EQ(viewRecord.at("error"), json::parse(readFile(out / (id + "_frames.json")))[6].at("error"));
  };
  expectSameFigures(json::parse(readFile(sm)), "sm");
  // Play shows one animation frame per displayed frame: `play` at frame 0, then six
  // displayed frames (five of `frames 5`, one of `pause`) reach frame 6.
  expectSameFigures(json::parse(readFile(pcf)), "pcf");

  // A step back is no pair of consecutive frames: the running figures start again there.
  const json viewBack = json::parse(readFile(back));
  EXPECT_EQ(viewBack.at("frame").get<int>(), 4);
  EXPECT_EQ(viewBack.at("temporal").at("first_frame").get<int>(), 4);
  EXPECT_EQ(viewBack.at("temporal").at("frame_pairs").get<int>(), 0);
}

// Bad input fails with exit 2 and one line before any window opens: these run without a
// display, where opening one would fail differently (exit 1).
TEST(ViewerBadInput, ExitsTwoWithOneLineBeforeAnyWindow) {
  const TempDir dir("testbed-viewer-bad");
  writeFile(dir / "bad.txt", "orbit 10 0\n\nmode sepia\n");
  writeFile(dir / "set.txt", "technique pcf\nset kernel=4\n");
  writeFile(dir / "play.txt", "play\n");
  writeFile(dir / "seek.txt", "seek 48\n");
  writeFile(dir / "far.txt", "orbit 10 0\nzoom 1e30\nscreenshot " + (dir / "x.png").string() + "\n");
  const std::string wall = scene("wall.json").string();
  struct Case {
    std::vector<std::string> args;
    std::string expected;  // in the one line
  };
  const std::vector<Case> cases = {
      {{"--scene", wall, "--script", (dir / "bad.txt").string()}, (dir / "bad.txt").string() + ":3: mode:"},
      {{"--scene", wall, "--script", (dir / "set.txt").string()}, (dir / "set.txt").string() + ":2: --set kernel=4"},
      {{"--scene", wall, "--script", (dir / "none.txt").string()}, "none.txt: no such file"},
      {{"--scene", (dir / "missing.json").string()}, "missing.json"},
      {{"--scene", wall, "--technique", "nope"}, "nope"},
      {{"--scene", wall, "--set", "bias=nan"}, "--set bias=nan"},
      {{"--scene", wall, "--backend", "osmesa"}, "--backend: view draws into a window"},
      {{"--scene", wall, "--frames", "2", "--screenshot", (dir / "x.jpg").string()}, "--screenshot:"},
      {{"--scene", wall, "--frames", "0"}, "--frames: 0 is outside 1..100000"},
      {{"--scene", wall, "--screenshot", (dir / "x.png").string()}, "--frames"},
      {{"--scene", wall, "--size", "12x"}, "--size"},
      {{"--scene", wall, "--script", (dir / "play.txt").string()}, (dir / "play.txt").string() + ":1: the scene has no animation"},
      {{"--scene", spinning().string(), "--script", (dir / "seek.txt").string()}, (dir / "seek.txt").string() + ":1: seek:"},
      {{"--scene", wall, "--script", (dir / "far.txt").string()}, (dir / "far.txt").string() + ":2: zoom: camera.eye:"},
  };
  for (const auto& c : cases) {
    const RunResult run = testbed(with({"view"}, c.args));
    EXPECT_EQ(run.exitCode, 2) << c.expected << "\n" << run.err;
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
  }
  EXPECT_FALSE(fs::exists(dir / "x.png"));
}

}  // namespace
