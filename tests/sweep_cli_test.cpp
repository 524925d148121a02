// `testbed sweep` and `testbed merge` end to end (docs/paper-runs.md "Paper runs"): bad specs and
// shards are one line and exit 2 with nothing written; a whole run writes the records,
// table, plot and close-up figure; shards joined by merge hold the same cells as a whole
// run; merge refuses shards of other specs or builds, missing or doubled shards, and keeps
// records of different backends in tables of their own.
#include <algorithm>
#include <filesystem>
#include <map>
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
TEST(CliSweep, AMisnamedPassIsRefusedBeforeAnyCellRenders) {
  TempDir tmp("sweep-pass");
  json spec = json::parse(readFile(tinySpecFile()));
  spec["scenes"]["wall"] = (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json").string();
  spec["rows"][1]["passes"] = {"visibility", "penumbra"};
  writeFile(tmp / "bad-pass.json", spec.dump());
  const RunResult run = runTestbed({"sweep", "--spec", (tmp / "bad-pass.json").string(), "--out", (tmp / "out").string()});
  EXPECT_EQ(run.exitCode, 2) << run.describe();
  // The techniques' declared passes are checked against the spec before the first cell.
  EXPECT_NE(run.err.find("bad-pass.json: rows[1].passes: pcf declares no pass 'penumbra'"), std::string::npos)
      << run.describe();
  EXPECT_EQ(run.err.find("[1/"), std::string::npos) << run.describe();
  EXPECT_FALSE(fs::exists(tmp / "out")) << run.describe();
}

TEST(CliSweep, WholeRunWritesRecordsTableAndFigure) {
  TempDir tmp("sweep-whole");
  const RunResult run = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--out", (tmp / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  // pcf's output is filtered: by default it is judged against the area-light reference too,
  // rendered once for both map sizes (docs/paper-runs.md "Reference").
  EXPECT_NE(run.err.find("[2/6] area-light reference (64 samples) on wall"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("[6/6] pcf on wall (160x90, map 128²"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("ETA"), std::string::npos) << run.err;
  const json records = json::parse(readFile(tmp / "out" / "records.json"));
  ASSERT_EQ(records.size(), 5u);  // one groundtruth (it uses no shadow map), per map size sm and pcf
  for (std::size_t i = 0; i < records.size(); ++i) {
    EXPECT_EQ(records[i]["cell"], i);
    EXPECT_TRUE(records[i]["error"].is_object()) << records[i].dump();
    EXPECT_TRUE(records[i]["row"].is_string() && records[i]["column"].is_string()) << records[i].dump();
  }
  EXPECT_EQ(records[4]["row"], "PCF 3 × 3");
  EXPECT_EQ(records[4]["column"], "128²");
  EXPECT_FALSE(fs::exists(tmp / "out" / ".testbed-resume"));  // removed once records.json holds the cells
  const std::string md = readFile(tmp / "out" / "tiny.md");
  EXPECT_NE(md.find("| PCF 3 × 3 |"), std::string::npos) << md;
  EXPECT_NE(md.find("- command: testbed sweep"), std::string::npos) << md;
  EXPECT_NE(md.find("- backend: osmesa"), std::string::npos) << md;
  for (const char* file : {"tiny.json", "tiny.png", "tiny.svg", "tiny-closeup-wall.png", "sweep.json", "spec.json"})
    EXPECT_TRUE(fs::exists(tmp / "out" / file)) << file;
}

// The plots are staged with the tables: when matplotlib fails (here a $TESTBED_PYTHON that
// exits 1), nothing is committed rather than tables without their plots, and the line says
// which table and how to go without plots. The cells stay saved for the rerun.
TEST(CliSweep, AFailingPlotCommitsNothing) {
  TempDir tmp("sweep-plot-fails");
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--out", out.string()},
                                   {.cwd = {}, .env = {{"TESTBED_PYTHON", "/bin/false"}}});
  EXPECT_EQ(run.exitCode, 1) << run.describe();
  EXPECT_NE(run.err.find("sweep_plot.py failed on " + (out / "tiny.json").string()), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--no-plot skips plots"), std::string::npos) << run.err;
  for (const char* file : {"tiny.md", "tiny.json", "tiny.png", "records.json", "index.html"})
    EXPECT_FALSE(fs::exists(out / file)) << file;
  const RunResult again = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--no-plot", "--out", out.string()});
  ASSERT_EQ(again.exitCode, 0) << again.describe();
  EXPECT_NE(again.err.find("sweep: resuming: 5 cells"), std::string::npos) << again.err;
  EXPECT_TRUE(fs::exists(out / "tiny.md"));
  EXPECT_FALSE(fs::exists(out / "tiny.png"));
}

TEST(CliMerge, ShardsJoinIntoTheWholeRunsCellsAndMismatchesAreRefused) {
  TempDir tmp("sweep-merge");
  const std::string spec = tinySpecFile().string();
  for (const char* shard : {"1/2", "2/2"}) {
    const RunResult run = runTestbed({"sweep", "--spec", spec, "--shard", shard, "--out",
                                (tmp / ("shard" + std::string(1, shard[0]))).string()});
    ASSERT_EQ(run.exitCode, 0) << run.describe();
  }
  const RunResult whole =
      runTestbed({"sweep", "--spec", spec, "--plugin", TESTBED_GATE_PLUGIN, "--no-plot", "--out", (tmp / "whole").string()});
  ASSERT_EQ(whole.exitCode, 0) << whole.describe();
  const RunResult merged = runTestbed({"merge", "--no-plot", "--out", (tmp / "merged").string(), (tmp / "shard1").string(),
                                 (tmp / "shard2").string()});
  ASSERT_EQ(merged.exitCode, 0) << merged.describe();
  EXPECT_EQ(cellsOf(json::parse(readFile(tmp / "merged" / "records.json"))),
            cellsOf(json::parse(readFile(tmp / "whole" / "records.json"))));
  EXPECT_TRUE(fs::exists(tmp / "merged" / "tiny.md"));
  EXPECT_TRUE(fs::exists(tmp / "merged" / "tiny-closeup-wall.png"));
  // The command as typed back by the shared command-line writer: options in declared order, shards last.
  EXPECT_EQ(json::parse(readFile(tmp / "merged" / "sweep.json")).at("command"),
            "testbed merge --out " + (tmp / "merged").string() + " --no-plot " + (tmp / "shard1").string() + " " +
                (tmp / "shard2").string());

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

// A folder of two scenes as `testbed corpus` writes them (manifest.json beside them).
fs::path sceneFolder(const fs::path& dir) {
  fs::create_directories(dir);
  for (const char* name : {"wall.json", "bunny.json"}) fs::copy_file(fs::path(TESTBED_SOURCE_DIR) / "scenes" / name, dir / name);
  writeFile(dir / "manifest.json", "{}");
  return dir;
}

json studySpec(const fs::path& scenes) {
  return {{"name", "study"}, {"scenes", scenes.string()}, {"settings", {{"size", "160x90"}}}, {"measure", "mismatch_pct"},
          {"axes", {{"shadow_map", {32, 64, 128}}}}, {"techniques", {"sm", "pcf"}}};
}

// A study over a corpus folder: scenes × sizes × techniques expanded by the sweep, one
// ground truth per scene, an error metric as the measure, no paper columns.
TEST(CliSweep, StudyOverACorpusFolderRendersEachGroundTruthOnce) {
  TempDir tmp("sweep-study");
  writeFile(tmp / "study.json", studySpec(sceneFolder(tmp / "scenes")).dump());
  const RunResult run = runTestbed({"sweep", "--spec", (tmp / "study.json").string(), "--no-plot", "--out", (tmp / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  std::size_t truths = 0;
  for (std::size_t at = run.err.find("] groundtruth on"); at != std::string::npos; at = run.err.find("] groundtruth on", at + 1)) ++truths;
  EXPECT_EQ(truths, 2u) << run.err;  // bunny and wall, each for all three map sizes
  const json records = json::parse(readFile(tmp / "out" / "records.json"));
  ASSERT_EQ(records.size(), 2u + 2u * 3u * 2u);
  for (const auto& r : records) {
    EXPECT_TRUE(r["error"]["pixels"]["receivers"].get<int>() > 0) << r.dump();
    EXPECT_EQ(r["error"]["pixels"]["denominators"]["leak_pct"], "far_shadow");
    EXPECT_TRUE(r.contains("row") && r.contains("column")) << r.dump();
  }
  const std::string md = readFile(tmp / "out" / "study.md");
  EXPECT_NE(md.find("Measure: `mismatch_pct` (%)"), std::string::npos) << md;
  EXPECT_NE(md.find("| technique | bunny · 32² |"), std::string::npos) << md;
  EXPECT_EQ(md.find(" paper |"), std::string::npos) << md;  // no paper columns
}

// A light below the receiver leaves the frame entirely unlit: a warning line, and every
// record of the frame flagged (excluded from statistics) with its denominators.
TEST(CliSweep, AGroundTruthThatCannotRankTechniquesIsFlagged) {
  TempDir tmp("sweep-flag");
  json scene = json::parse(readFile(fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json"));
  scene["light"]["eye"] = {0, -60, -60};
  fs::create_directories(tmp / "scenes");
  writeFile(tmp / "scenes" / "under.json", scene.dump());
  json spec = studySpec(tmp / "scenes");
  spec["axes"]["shadow_map"] = {32};
  spec["techniques"] = {"sm"};
  writeFile(tmp / "study.json", spec.dump());
  const RunResult run = runTestbed({"sweep", "--spec", (tmp / "study.json").string(), "--no-plot", "--out", (tmp / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_NE(run.err.find("sweep: warning: under at 160x90: the ground truth is entirely unlit from the camera"),
            std::string::npos) << run.err;
  const json records = json::parse(readFile(tmp / "out" / "records.json"));
  ASSERT_EQ(records.size(), 2u);
  for (const auto& r : records) {
    EXPECT_EQ(r["error"]["flag"], "entirely unlit from the camera") << r.dump();
    EXPECT_EQ(r["error"]["pixels"]["gt_lit"], 0);
    EXPECT_EQ(r["error"]["pixels"]["far_shadow"], r["error"]["pixels"]["receivers"]);
  }
}

// Bad studies: one line naming the field, exit 2, nothing written.
TEST(CliSweep, BadStudiesNameTheFieldAndWriteNothing) {
  TempDir tmp("sweep-bad-study");
  fs::create_directories(tmp / "empty");
  const fs::path scenes = sceneFolder(tmp / "scenes");
  struct Case {
    json spec;
    std::string expected;
  };
  json metric = studySpec(scenes);
  metric["measure"] = "joules";
  const std::vector<Case> cases = {
      {studySpec(tmp / "missing"), "scenes: no such scene file or folder"},
      {studySpec(tmp / "scenes" / "*.scene"), "matches no scene file"},
      {studySpec(tmp / "empty"), "holds no scene file (an empty corpus?)"},
      {metric, "measure: expected a metric of the metric table"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path spec = tmp / ("bad" + std::to_string(i) + ".json");
    writeFile(spec, cases[i].spec.dump());
    const RunResult run = runTestbed({"sweep", "--spec", spec.string(), "--out", (tmp / "out").string()});
    EXPECT_EQ(run.exitCode, 2) << run.describe();
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.describe();
    EXPECT_NE(run.err.find(spec.string() + ": "), std::string::npos) << run.describe();
    EXPECT_NE(run.err.find(cases[i].expected), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(tmp / "out")) << run.describe();
  }
}

// A sweep killed mid-run and run again skips the cells it finished (verified, not trusted:
// an edited one runs again) and ends with the records of an uninterrupted run.
TEST(CliSweep, AKilledSweepResumesWhereItStopped) {
  TempDir tmp("sweep-resume");
  json study = studySpec(sceneFolder(tmp / "scenes"));
  study["techniques"].push_back("test-gate");
  writeFile(tmp / "study.json", study.dump());
  const std::string spec = (tmp / "study.json").string(), out = (tmp / "out").string();
  // Killed (SIGTERM, as Slurm's scancel) while it waits at the gate of its first test-gate
  // cell (tests/gate_plugin): the cells before it are on disk, the rest are not.
  TechniqueGate gate(tmp / "gate", "gate");
  {
    BackgroundRun sweep({TESTBED_BINARY, "sweep", "--spec", spec, "--plugin", TESTBED_GATE_PLUGIN, "--no-plot", "--out", out},
                        {{"TESTBED_TEST_GATE", (tmp / "gate").string()}}, out + ".log");
    ASSERT_TRUE(gate.waitUntilReached([&] { return sweep.ended(); })) << readFile(out + ".log");
    sweep.stop(SIGTERM);
  }
  ASSERT_FALSE(fs::exists(tmp / "out" / "records.json")) << "the sweep went past the gate";
  gate.open();
  // One finished cell edited: it must run again, not be trusted.
  std::vector<fs::path> cells;
  for (const auto& entry : fs::directory_iterator(tmp / "out" / ".testbed-resume"))
    if (entry.path().extension() == ".json" && entry.path().filename().string().rfind("cell-", 0) == 0) cells.push_back(entry.path());
  ASSERT_GE(cells.size(), 3u);
  std::sort(cells.begin(), cells.end());
  json edited = json::parse(readFile(cells.back()));
  edited["record"]["shadow_map"] = 4096;
  writeFile(cells.back(), edited.dump());

  const RunResult resumed = runTestbed({"sweep", "--spec", spec, "--plugin", TESTBED_GATE_PLUGIN, "--no-plot", "--out", out});
  ASSERT_EQ(resumed.exitCode, 0) << resumed.describe();
  EXPECT_NE(resumed.err.find("sweep: resuming: " + std::to_string(cells.size() - 1) + " cells"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find(cells.back().filename().string() + ": record.shadow_map: 4096"), std::string::npos) << resumed.err;
  const RunResult whole =
      runTestbed({"sweep", "--spec", spec, "--plugin", TESTBED_GATE_PLUGIN, "--no-plot", "--out", (tmp / "whole").string()});
  ASSERT_EQ(whole.exitCode, 0) << whole.describe();
  const json a = json::parse(readFile(tmp / "out" / "records.json")), b = json::parse(readFile(tmp / "whole" / "records.json"));
  EXPECT_EQ(cellsOf(a), cellsOf(b));
  EXPECT_EQ(errorsOf(a), errorsOf(b));
  EXPECT_FALSE(fs::exists(tmp / "out" / ".testbed-resume"));
  // Run once more: every record is there and valid; only the close-up figure's cells (the
  // first column, bunny at 32²), whose images a whole run does not keep, render again.
  const RunResult again = runTestbed({"sweep", "--spec", spec, "--plugin", TESTBED_GATE_PLUGIN, "--no-plot", "--out", out});
  ASSERT_EQ(again.exitCode, 0) << again.describe();
  EXPECT_NE(again.err.find("sweep: resuming: " + std::to_string(b.size() - 4) + " cells"), std::string::npos) << again.err;
  EXPECT_EQ(again.err.find("on wall"), std::string::npos) << again.err;
}

}  // namespace
}  // namespace testbed::test
