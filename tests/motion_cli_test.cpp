// `--frames` end to end through the binary at a small size (docs/motion.md): the outputs of
// a sequence, the ground truth against itself reading 0 on every temporal figure, a
// technique on an animation in which nothing moves reading 0 flicker and 0 crawl, and the
// refusals of --frames and of a bad animation block (exit 2, one line, nothing written).
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/report/frame_sheet.h"
#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace testbed::test;

const std::vector<std::string> kMotionRunSize = {"--size", "96x64", "--shadow-map", "128"};

fs::path bundled(const std::string& name) { return fs::path(TESTBED_SOURCE_DIR) / "scenes" / name; }
fs::path animated(const std::string& name) { return bundled("motion/" + name); }

json readJson(const fs::path& file) { return json::parse(readFile(file)); }

void expectTemporalZero(const json& sequence) {
  SCOPED_TRACE(sequence.at("technique").get<std::string>());
  ASSERT_TRUE(sequence.contains("temporal")) << sequence.dump();
  EXPECT_EQ(sequence.at("temporal").at("flicker").get<double>(), 0.0);
  EXPECT_EQ(sequence.at("temporal").at("crawl_pct").get<double>(), 0.0);
  EXPECT_EQ(sequence.at("temporal").at("crawl_missed_pct").get<double>(), 0.0);
  EXPECT_GT(sequence.at("temporal").at("stable_pairs").get<double>(), 0.0);
}

TEST(MotionCli, CompareWritesSequenceOutputsAndGroundTruthReadsZero) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed(with({"compare", "--scene", animated("spinning_occluder.json").string(),
                                         "--techniques", "sm", "--frames", "0:4:2", "--out", out.string()},
                                        kMotionRunSize));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_NE(run.err.find("[3/3] frame 4 of "), std::string::npos) << run.err;  // one step per frame of 0:4:2
  EXPECT_NE(run.err.find("ETA"), std::string::npos) << run.err;
  for (const char* name : {"report.md", "sequence.json", "groundtruth.mp4", "sm.mp4", "sm_frames.json",
                           "sm_sequence.json", "sm_error_over_time.png", "groundtruth_sequence.json"})
    EXPECT_TRUE(fs::is_regular_file(out / name)) << name;
  EXPECT_GT(fs::file_size(out / "sm.mp4"), 0u);

  const json frames = readJson(out / "sm_frames.json");
  ASSERT_EQ(frames.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(frames[i].at("frame").get<int>(), int(2 * i));
    EXPECT_EQ(frames[i].at("light_fit").get<std::string>(), "per frame");
    EXPECT_TRUE(frames[i].at("error").contains("rmse"));
    EXPECT_EQ(frames[i].contains("temporal"), i > 0) << "a pair closes from the second frame on";
  }
  const json sm = readJson(out / "sm_sequence.json");
  EXPECT_EQ(sm.at("frames").at("count").get<int>(), 3);
  EXPECT_EQ(sm.at("light_fit").get<std::string>(), "per frame");
  const json& rmse = sm.at("series").at("rmse");
  EXPECT_LE(rmse.at("mean").get<double>(), rmse.at("max").get<double>());
  EXPECT_EQ(sm.at("temporal").at("frame_pairs").get<int>(), 2);
  // The camera stays: the previous frame is the held view, nothing is rendered twice. The
  // blade turns: its pixels see other points from frame to frame and are not paired.
  EXPECT_EQ(sm.at("temporal").at("held_renders").get<int>(), 0);
  EXPECT_GT(sm.at("temporal").at("moved_pixels").get<double>(), 0.0);
  EXPECT_EQ(frames[1].at("temporal").at("held_render").get<bool>(), false);
  expectTemporalZero(readJson(out / "groundtruth_sequence.json"));
  EXPECT_NE(readFile(out / "report.md").find("| sm |"), std::string::npos);
}

TEST(MotionCli, NothingMovingReadsZeroFlickerAndCrawl) {
  TempDir tmp;
  json scene = readJson(animated("spinning_occluder.json"));
  scene["animation"] = {{"frames", 3}};  // frames, but every part static
  const fs::path file = writeFile(tmp / "still.json", scene.dump());
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed(with({"compare", "--scene", file.string(), "--techniques", "sm,pcf,vsm",
                                         "--frames", "all", "--no-plot", "--out", out.string()},
                                        kMotionRunSize));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  for (const auto& sequence : readJson(out / "sequence.json")) expectTemporalZero(sequence);
  EXPECT_FALSE(fs::exists(out / "sm_error_over_time.png"));
}

TEST(MotionCli, RenderWritesASequenceWithoutTemporalFigures) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed(with({"render", "--scene", animated("fence_dolly.json").string(), "--technique",
                                         "sm", "--frames", "46:47", "--out", out.string()},
                                        kMotionRunSize));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const json sm = readJson(out / "sm_sequence.json");
  EXPECT_EQ(sm.at("frames").at("first").get<int>(), 46);
  EXPECT_FALSE(sm.contains("temporal"));
  EXPECT_TRUE(fs::is_regular_file(out / "sm.mp4"));
  // Both frames kept on the shaded sheet (no error sheet without a comparison), so one frame
  // can be looked at without a video decoder.
  const testbed::SheetLayout layout = testbed::sheetLayout({sm.at("width").get<int>(), sm.at("height").get<int>()}, 2);
  const testbed::ImageF sheet = testbed::readImage(out / "sm_frames_shaded.png");
  EXPECT_EQ(glm::ivec2(sheet.width, sheet.height), layout.sheetSize());
  EXPECT_FALSE(fs::exists(out / "sm_frames_error.png"));
}

TEST(MotionCli, BadFramesAndBadAnimationBlocksAreRefused) {
  TempDir tmp;
  json bad = readJson(animated("spinning_occluder.json"));
  bad["animation"]["frames"] = 0;
  const fs::path badScene = writeFile(tmp / "bad.json", bad.dump());
  struct Case {
    std::vector<std::string> args;
    std::string names;
  };
  const std::string spinning = animated("spinning_occluder.json").string();
  const std::vector<Case> cases = {
      {{"render", "--scene", bundled("wall.json").string(), "--technique", "sm", "--frames", "0:1"}, "frame 0 only"},
      {{"compare", "--scene", spinning, "--techniques", "sm", "--frames", "5:2"}, "--frames"},
      {{"groundtruth", "--scene", spinning, "--frames", "0:48"}, "frames 0..47"},
      {{"render", "--scene", spinning, "--technique", "sm", "--frames", "0-4"}, "A:B[:STEP]"},
      {{"render", "--scene", spinning, "--technique", "sm", "--frames", "0:4:0"}, "STEP"},
      {{"render", "--scene", badScene.string(), "--technique", "sm"}, "animation.frames"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path out = tmp / ("out" + std::to_string(i));
    const RunResult run = runTestbed(with(with(cases[i].args, {"--out", out.string()}), kMotionRunSize));
    EXPECT_TRUE(rejectedWithOneLine(run)) << i;
    EXPECT_NE(run.err.find(cases[i].names), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out)) << "nothing written";
  }
}

}  // namespace
