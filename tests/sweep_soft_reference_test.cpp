// A sweep's reference (docs/paper-runs.md "Reference"): "both" judges every technique
// against the area-light reference too, and every filtered technique's record holds every
// soft metric with the reference it was taken against; by default only filtered outputs
// are; the reference is rendered once per scene and output size, not per map size, and a
// resumed run renders none it does not need; bad values are one line naming the field.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/harness/metric_table.h"
#include "testbed/technique/registry.h"
#include "tests/sweep_test_support.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The wall scene (light radius 2) at 160×90 under two map sizes: one area-light reference
// serves both.
json softSpec(const std::vector<std::string>& techniques) {
  return {{"name", "soft"},
          {"scenes", {{"wall", (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json").string()}}},
          {"settings", {{"size", "160x90"}, {"reference", "both"}, {"area_samples", 16}}},
          {"measure", "soft_rmse"},
          {"axes", {{"shadow_map", {64, 128}}}},
          {"techniques", techniques}};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

std::vector<std::string> softMetricPaths() {
  std::vector<std::string> paths;
  for (const Metric& m : metricTable())
    if (m.reference == MetricReference::Soft) paths.emplace_back(m.path);
  return paths;
}

TEST(SweepSoftReference, BothGivesEveryFilteredTechniqueEverySoftMetric) {
  TempDir tmp("sweep-soft");
  std::vector<std::string> techniques = {"sm"}, filtered;
  for (const auto& t : registeredTechniques())
    if (t.info->output == OutputKind::Filtered) filtered.push_back(t.info->id);
  ASSERT_GE(filtered.size(), 5u);  // pcf, vsm, esm, evsm, msm, the revectorized filters, edtsm
  techniques.insert(techniques.end(), filtered.begin(), filtered.end());
  writeFile(tmp / "soft.json", softSpec(techniques).dump());
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed({"sweep", "--spec", (tmp / "soft.json").string(), "--no-plot", "--out", out.string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_EQ(count(run.err, "] area-light reference (16 samples) on wall"), 1u) << run.err;  // not once per map size
  const json records = json::parse(readFile(out / "records.json"));
  ASSERT_EQ(records.size(), 1 + 2 * techniques.size());
  const std::vector<std::string> soft = softMetricPaths();
  ASSERT_EQ(soft.size(), 4u);  // soft_rmse, penumbra MAE, outside-penumbra MAE, umbra leak
  std::size_t judged = 0;
  for (const auto& r : records) {
    if (r["technique"] == "groundtruth") {
      EXPECT_TRUE(r["error"]["soft_rmse"].is_null()) << r.dump();
      continue;
    }
    for (const auto& path : soft) EXPECT_TRUE(r.at(json::json_pointer(path)).is_number()) << path << " " << r.dump();
    EXPECT_EQ(r["area_reference"], json({{"samples", 16}, {"light_radius", 2.0}})) << r.dump();
    EXPECT_EQ(r["error"]["reference"]["soft_umbra_leak"], "soft");
    ++judged;
  }
  EXPECT_EQ(judged, 2 * techniques.size());
  // The table's measure is a soft metric: a figure in every technique's row.
  const std::string md = readFile(out / "soft.md");
  EXPECT_NE(md.find("Measure: `soft_rmse`"), std::string::npos) << md;
  EXPECT_NE(md.find("- reference: both: every technique against the hard ground truth and the area-light reference "
                    "(16 samples, each scene's light radius)"),
            std::string::npos)
      << md;
  // The page's table of every cell shows every soft metric (their headings, from the metric table).
  const std::string page = readFile(out / "index.html");
  for (const Metric& m : metricTable())
    if (m.reference == MetricReference::Soft) EXPECT_NE(page.find(std::string(m.heading)), std::string::npos) << m.name;

  // Run again: the 128² cells resume; the figure column's (64²) run again, since a whole
  // run keeps no figure images (docs/paper-runs.md "Resuming"), and the reference with
  // them, once; the errors are the first run's.
  const RunResult again = runTestbed({"sweep", "--spec", (tmp / "soft.json").string(), "--no-plot", "--out", out.string()});
  ASSERT_EQ(again.exitCode, 0) << again.describe();
  EXPECT_NE(again.err.find("resuming: " + std::to_string(techniques.size()) + " cells"), std::string::npos) << again.err;
  EXPECT_EQ(count(again.err, "] area-light reference (16 samples) on wall"), 1u) << again.err;
  EXPECT_EQ(errorsOf(json::parse(readFile(out / "records.json"))), errorsOf(records));
}

TEST(SweepSoftReference, ByDefaultOnlyFilteredOutputsAreJudgedByTheAreaLight) {
  TempDir tmp("sweep-soft-default");
  json spec = softSpec({"sm", "pcf"});
  spec["settings"].erase("reference");
  spec["measure"] = "mismatch_pct";
  writeFile(tmp / "spec.json", spec.dump());
  // Two shards: each renders the reference once for the cells it owns that need it.
  for (const char* shard : {"1/2", "2/2"}) {
    const fs::path out = tmp / (std::string("shard-") + shard[0]);
    const RunResult run =
        runTestbed({"sweep", "--spec", (tmp / "spec.json").string(), "--shard", shard, "--no-plot", "--out", out.string()});
    ASSERT_EQ(run.exitCode, 0) << run.describe();
    EXPECT_LE(count(run.err, "] area-light reference"), 1u) << run.err;
  }
  const RunResult merged =
      runTestbed({"merge", "--no-plot", "--out", (tmp / "merged").string(), (tmp / "shard-1").string(), (tmp / "shard-2").string()});
  ASSERT_EQ(merged.exitCode, 0) << merged.describe();
  const json records = json::parse(readFile(tmp / "merged" / "records.json"));
  ASSERT_EQ(records.size(), 5u);
  for (const auto& r : records) {
    const bool filtered = r["technique"] == "pcf";
    EXPECT_EQ(r["error"]["soft_rmse"].is_number(), filtered) << r.dump();
    EXPECT_EQ(r["error"].contains("soft_penumbra_mae"), filtered) << r.dump();
    EXPECT_EQ(r.contains("area_reference"), filtered) << r.dump();
  }
}

TEST(SweepSoftReference, BadReferencesAreOneLineNamingTheFieldAndWriteNothing) {
  TempDir tmp("sweep-soft-bad");
  struct Case {
    json spec;
    std::string expected;
  };
  std::vector<Case> cases;
  auto with = [&](const std::string& key, const json& value, const std::string& expected) {
    json spec = softSpec({"sm", "pcf"});
    spec["settings"][key] = value;
    cases.push_back({spec, expected});
  };
  with("reference", "area", "settings.reference: expected \"hard\", \"soft\", \"both\" or \"by_output\", got \"area\"");
  with("area_samples", 0, "settings.area_samples: must be an integer in [1, 4096], got 0");
  with("light_radius", -1, "settings.light_radius: expected a number in (0, 1e6]");
  json hard = softSpec({"sm"});
  hard["settings"]["reference"] = "hard";
  hard["settings"].erase("area_samples");
  cases.push_back({hard, "measure: \"soft_rmse\" is measured against the area-light reference"});
  hard["measure"] = "mismatch_pct";
  hard["settings"]["area_samples"] = 8;
  cases.push_back({hard, "settings.area_samples: the spec's reference is hard"});
  json frames = softSpec({"sm"});
  frames["frames"] = "all";
  cases.push_back({frames, "measure: \"soft_rmse\" is measured against the area-light reference, which a spec over"});
  frames["measure"] = "mismatch_pct";
  cases.push_back({frames, "settings.reference: both: not available with \"frames\""});
  json flat = softSpec({"sm"});  // stacked_occluders' light has no radius
  flat["scenes"] = {{"stacked", (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "stacked_occluders.json").string()}};
  cases.push_back({flat, "settings.reference: both, but scene stacked's light has no radius"});
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path spec = tmp / ("bad" + std::to_string(i) + ".json");
    writeFile(spec, cases[i].spec.dump());
    const RunResult run = runTestbed({"sweep", "--spec", spec.string(), "--no-plot", "--out", (tmp / "out").string()});
    EXPECT_EQ(run.exitCode, 2) << run.describe();
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.describe();
    EXPECT_NE(run.err.find(spec.string() + ": " + cases[i].expected), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(tmp / "out")) << run.describe();
  }
}

}  // namespace
}  // namespace testbed::test
