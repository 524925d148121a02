// `testbed sweep` and `testbed merge` end to end (docs/paper-runs.md "Paper runs"): bad specs and
// shards are one line and exit 2 with nothing written; a whole run writes the records,
// table, plot and close-up figure; shards joined by merge hold the same cells as a whole
// run; merge refuses shards of other specs or builds, missing or doubled shards, and keeps
// records of different backends in tables of their own.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/sweep_test_support.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

TEST(CliSweep, BadSpecsAndShardsAreOneLineAndWriteNothing) {
  TempDir tmp("sweep-bad");
  json spec = json::parse(readFile(tinySpecFile()));
  spec["scenes"]["wall"] = (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json").string();
  spec["rows"][1]["colour"] = "red";
  writeFile(tmp / "unknown-key.json", spec.dump());
  spec["rows"][1].erase("colour");
  spec["columns"][0]["shadow_map"] = "big";
  writeFile(tmp / "wrong-type.json", spec.dump());
  writeFile(tmp / "nan.json", R"({"name": "x", "citation": "c", "scenes": {}, "columns": [NaN], "rows": []})");
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"--spec", (tmp / "unknown-key.json").string()}, "unknown-key.json: rows[1].colour: unknown key"},
      {{"--spec", (tmp / "wrong-type.json").string()}, "wrong-type.json: columns[0].shadow_map: expected an integer"},
      {{"--spec", (tmp / "nan.json").string()}, "nan.json: line 1, column"},
      {{"--spec", (tmp / "missing.json").string()}, "missing.json: no such file"},
      {{"--spec", tinySpecFile().string(), "--shard", "3/2"}, "--shard: expected K/N"},
      {{"--spec", tinySpecFile().string(), "--size", "big"}, "--size: expected WxH"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"sweep", "--out", (tmp / "out").string()};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const RunResult run = runTestbed(args);
    EXPECT_EQ(run.exitCode, 2) << run.describe();
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.describe();
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(tmp / "out")) << run.describe();
  }
}

// A row naming a pass its technique lacks stops the sweep at that cell's first render
// (techniques report their passes only by rendering), not after every cell.
TEST(CliSweep, AMisnamedPassStopsAtTheFirstCellThatHasIt) {
  TempDir tmp("sweep-pass");
  json spec = json::parse(readFile(tinySpecFile()));
  spec["scenes"]["wall"] = (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json").string();
  spec["rows"][1]["passes"] = {"visibility", "penumbra"};
  writeFile(tmp / "bad-pass.json", spec.dump());
  const RunResult run = runTestbed({"sweep", "--spec", (tmp / "bad-pass.json").string(), "--out", (tmp / "out").string()});
  EXPECT_EQ(run.exitCode, 2) << run.describe();
  EXPECT_NE(run.err.find("bad-pass.json: rows[1].passes: pcf has no pass 'penumbra'"), std::string::npos) << run.describe();
  EXPECT_NE(run.err.find("[3/6] pcf"), std::string::npos) << run.describe();  // the first pcf cell
  EXPECT_EQ(run.err.find("[4/6]"), std::string::npos) << run.describe();      // and nothing after it
  EXPECT_FALSE(fs::exists(tmp / "out")) << run.describe();
}

TEST(CliSweep, WholeRunWritesRecordsTableAndFigure) {
  TempDir tmp("sweep-whole");
  const RunResult run = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--out", (tmp / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_NE(run.err.find("[6/6] pcf on wall (160x90, map 128²"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("ETA"), std::string::npos) << run.err;
  const json records = json::parse(readFile(tmp / "out" / "records.json"));
  ASSERT_EQ(records.size(), 6u);  // per map size: groundtruth, sm, pcf
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_EQ(records[i]["cell"], i);
    EXPECT_TRUE(records[i]["error"].is_object()) << records[i].dump();
  }
  const std::string md = readFile(tmp / "out" / "tiny.md");
  EXPECT_NE(md.find("| PCF 3 × 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("- command: testbed sweep"), std::string::npos) << md;
  EXPECT_NE(md.find("- backend: osmesa"), std::string::npos) << md;
  for (const char* file : {"tiny.json", "tiny.png", "tiny.svg", "tiny-closeup-wall.png", "sweep.json", "spec.json"})
    EXPECT_TRUE(fs::exists(tmp / "out" / file)) << file;
}

TEST(CliMerge, ShardsJoinIntoTheWholeRunsCellsAndMismatchesAreRefused) {
  TempDir tmp("sweep-merge");
  const std::string spec = tinySpecFile().string();
  for (const char* shard : {"1/2", "2/2"}) {
    const RunResult run = runTestbed({"sweep", "--spec", spec, "--shard", shard, "--out",
                                (tmp / ("shard" + std::string(1, shard[0]))).string()});
    ASSERT_EQ(run.exitCode, 0) << run.describe();
  }
  const RunResult whole = runTestbed({"sweep", "--spec", spec, "--no-plot", "--out", (tmp / "whole").string()});
  ASSERT_EQ(whole.exitCode, 0) << whole.describe();
  const RunResult merged = runTestbed({"merge", "--no-plot", "--out", (tmp / "merged").string(), (tmp / "shard1").string(),
                                 (tmp / "shard2").string()});
  ASSERT_EQ(merged.exitCode, 0) << merged.describe();
  EXPECT_EQ(cellsOf(json::parse(readFile(tmp / "merged" / "records.json"))),
            cellsOf(json::parse(readFile(tmp / "whole" / "records.json"))));
  EXPECT_TRUE(fs::exists(tmp / "merged" / "tiny.md"));
  EXPECT_TRUE(fs::exists(tmp / "merged" / "tiny-closeup-wall.png"));

  // Another spec (other overrides count as another spec), another build, a missing or doubled shard.
  ASSERT_EQ(runTestbed({"sweep", "--spec", spec, "--shard", "2/2", "--shadow-map", "32", "--out", (tmp / "other").string()})
                .exitCode,
            0);
  fs::copy(tmp / "shard2", tmp / "rebuilt", fs::copy_options::recursive);
  json manifest = json::parse(readFile(tmp / "rebuilt" / "sweep.json"));
  manifest["build"] = "0000000000000000";
  writeFile(tmp / "rebuilt" / "sweep.json", manifest.dump());
  struct Case {
    std::vector<std::string> shards;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"shard1", "other"}, "other/sweep.json: spec_fingerprint: another spec"},
      {{"shard1", "rebuilt"}, "rebuilt/sweep.json: build: made by another testbed build"},
      {{"shard1"}, "merge: shard 2/2 is missing"},
      {{"shard1", "shard1"}, "shard1/sweep.json: shard: 1/2 given twice"},
      {{"shard1", "nowhere"}, "nowhere/sweep.json: missing"},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"merge", "--no-plot", "--out", (tmp / "refused").string()};
    for (const auto& s : c.shards) args.push_back((tmp / s).string());
    const RunResult run = runTestbed(args);
    EXPECT_EQ(run.exitCode, 2) << run.describe();
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.describe();
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(tmp / "refused")) << run.describe();
  }

  // A shard run on another backend: its records go to a table of their own.
  json records = json::parse(readFile(tmp / "shard2" / "records.json"));
  for (auto& r : records) r["backend"] = "egl: NVIDIA H200";
  writeFile(tmp / "shard2" / "records.json", records.dump());
  const RunResult apart = runTestbed({"merge", "--no-plot", "--out", (tmp / "apart").string(), (tmp / "shard1").string(),
                                (tmp / "shard2").string()});
  ASSERT_EQ(apart.exitCode, 0) << apart.describe();
  EXPECT_TRUE(fs::exists(tmp / "apart" / "tiny.egl-nvidia-h200.md"));
  EXPECT_FALSE(fs::exists(tmp / "apart" / "tiny.md"));
  const std::string egl = readFile(tmp / "apart" / "tiny.egl-nvidia-h200.md");
  EXPECT_NE(egl.find("- backend: egl: NVIDIA H200"), std::string::npos) << egl;
  EXPECT_NE(egl.find("—"), std::string::npos) << egl;  // shard 1's cells are not in this table
}

}  // namespace
}  // namespace testbed::test
