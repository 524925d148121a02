// Sweeps over frames end to end (docs/paper-runs.md "Frames"): a spec's "frames" runs each
// cell as a sequence whose record carries the sequence figures, a table can measure them,
// the sweep's figure equals `compare --frames`'s for the same cell, a still scene reads 0
// flicker, shards merge and a re-submitted shard resumes; a temporal measure without frames is refused.
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/sweep_test_support.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path spinningOccluder() { return fs::path(TESTBED_SOURCE_DIR) / "scenes" / "motion" / "spinning_occluder.json"; }

// sm and pcf over frames 0, 2 and 4 of `scene` at 96×64 and a 128² map.
json framesSpec(const fs::path& scene, const std::string& measure) {
  return {{"name", "motion"},
          {"scenes", {{"occluder", scene.string()}}},
          {"settings", {{"size", "96x64"}, {"shadow_map", 128}}},
          {"frames", "0:4:2"},
          {"measure", measure},
          {"columns", {{{"label", "128²"}}}},
          {"techniques", {"sm", "pcf"}}};
}

const json& recordOf(const json& records, const std::string& technique) {
  for (const auto& r : records)
    if (r.at("technique") == technique) return r;
  throw std::runtime_error("no record of " + technique);
}

TEST(SweepFrames, FlickerMatchesCompareFramesForTheSameCell) {
  TempDir tmp("sweep-frames");
  const fs::path spec = writeFile(tmp / "motion.json", framesSpec(spinningOccluder(), "flicker").dump());
  const RunResult sweep = runTestbed({"sweep", "--spec", spec.string(), "--no-plot", "--out", (tmp / "sweep").string()});
  ASSERT_EQ(sweep.exitCode, 0) << sweep.describe();
  EXPECT_NE(sweep.err.find("3 runs over 3 frames"), std::string::npos) << sweep.err;
  EXPECT_NE(sweep.err.find("ETA"), std::string::npos) << sweep.err;
  const RunResult compare = runTestbed({"compare", "--scene", spinningOccluder().string(), "--techniques", "sm,pcf",
                                        "--size", "96x64", "--shadow-map", "128", "--frames", "0:4:2", "--no-plot",
                                        "--out", (tmp / "compare").string()});
  ASSERT_EQ(compare.exitCode, 0) << compare.describe();

  const json records = json::parse(readFile(tmp / "sweep" / "records.json"));
  for (const std::string id : {"sm", "pcf"}) {
    SCOPED_TRACE(id);
    const json& record = recordOf(records, id);
    const json sequence = json::parse(readFile(tmp / "compare" / (id + "_sequence.json")));
    ASSERT_TRUE(record.contains("sequence")) << record.dump();
    EXPECT_EQ(record["sequence"]["frames"]["count"], 3);
    EXPECT_EQ(record["sequence"]["temporal"], sequence["temporal"]);
    EXPECT_EQ(record["sequence"]["series"]["rmse"], sequence["series"]["rmse"]);
    EXPECT_GT(record["sequence"]["temporal"]["flicker"].get<double>(), 0.0) << "the blade turns: edges move";
  }
  EXPECT_EQ(recordOf(records, "groundtruth")["sequence"]["temporal"]["flicker"], 0.0);
  // The table shows the figure the record holds (5 decimals for flicker).
  const std::string table = readFile(tmp / "sweep" / "motion.md");
  char sm[32];
  std::snprintf(sm, sizeof sm, "%.5f", recordOf(records, "sm")["sequence"]["temporal"]["flicker"].get<double>());
  EXPECT_NE(table.find(sm), std::string::npos) << table;
  EXPECT_NE(table.find("Measure: `flicker`"), std::string::npos) << table;

  // Shards of the same spec merge into the same records; a re-submitted shard finds its
  // cells (the ground truth and pcf) done.
  for (const char* shard : {"1/2", "2/2"}) {
    const RunResult run = runTestbed({"sweep", "--spec", spec.string(), "--shard", shard, "--out",
                                      (tmp / ("shard" + std::string(1, shard[0]))).string()});
    ASSERT_EQ(run.exitCode, 0) << run.describe();
  }
  const RunResult again = runTestbed({"sweep", "--spec", spec.string(), "--shard", "1/2", "--out", (tmp / "shard1").string()});
  ASSERT_EQ(again.exitCode, 0) << again.describe();
  EXPECT_NE(again.err.find("resuming: 2 cells of shard 1/2"), std::string::npos) << again.err;
  EXPECT_EQ(again.err.find("runs over"), std::string::npos) << "nothing left to render: " << again.err;
  const RunResult merged = runTestbed({"merge", "--no-plot", "--out", (tmp / "merged").string(),
                                       (tmp / "shard1").string(), (tmp / "shard2").string()});
  ASSERT_EQ(merged.exitCode, 0) << merged.describe();
  const json mergedRecords = json::parse(readFile(tmp / "merged" / "records.json"));
  EXPECT_EQ(cellsOf(mergedRecords), cellsOf(records));
  EXPECT_EQ(recordOf(mergedRecords, "sm")["sequence"]["temporal"], recordOf(records, "sm")["sequence"]["temporal"]);
}

TEST(SweepFrames, AStillSceneReadsZeroFlickerAndCrawl) {
  TempDir tmp("sweep-still");
  json scene = json::parse(readFile(spinningOccluder()));
  scene["animation"] = {{"frames", 3}};  // frames, but nothing moves
  const fs::path still = writeFile(tmp / "still.json", scene.dump());
  json spec = framesSpec(still, "crawl");
  spec["frames"] = "all";
  writeFile(tmp / "still-spec.json", spec.dump());
  const RunResult run = runTestbed({"sweep", "--spec", (tmp / "still-spec.json").string(), "--no-plot", "--out",
                                    (tmp / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  for (const auto& record : json::parse(readFile(tmp / "out" / "records.json"))) {
    SCOPED_TRACE(record["technique"].get<std::string>());
    EXPECT_EQ(record["sequence"]["temporal"]["flicker"], 0.0);
    EXPECT_EQ(record["sequence"]["temporal"]["crawl_pct"], 0.0);
    EXPECT_GT(record["sequence"]["temporal"]["stable_pairs"].get<double>(), 0.0);
  }
}

TEST(SweepFrames, TemporalMeasuresWithoutFramesAndRangesBeyondTheSceneAreRefused) {
  TempDir tmp("sweep-frames-bad");
  json noFrames = framesSpec(spinningOccluder(), "flicker");
  noFrames.erase("frames");
  json beyond = framesSpec(spinningOccluder(), "crawl");
  beyond["frames"] = "0:99";
  const std::vector<std::pair<json, std::string>> cases = {
      {noFrames, "bad.json: measure: \"flicker\" is a figure over frames: the spec needs \"frames\""},
      {beyond, "bad.json: frames: scene occluder: 0:99 is outside the scene's frames"},
  };
  for (const auto& [spec, expected] : cases) {
    writeFile(tmp / "bad.json", spec.dump());
    const RunResult run = runTestbed({"sweep", "--spec", (tmp / "bad.json").string(), "--out", (tmp / "out").string()});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(expected), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(tmp / "out"));
  }
}

}  // namespace
}  // namespace testbed::test
