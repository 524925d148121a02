#include "testbed/report/regression_check.h"

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "tests/cli_helpers.h"

namespace testbed {
namespace {

using nlohmann::json;

// A work block: a shadow-map and a visibility pass, each counting 1000 of everything.
json work() {
  json counts = json::object();
  for (const WorkCounter& counter : kWorkCounters) counts[std::string(counter.name)] = 1000;
  return {{"passes", {{"shadow-map", counts}, {"visibility", counts}}}, {"total", counts}};
}

// A compare record of `technique` on bunny at 512² (docs/record.md "The record").
json record(const std::string& technique, double wallMs = 20.0, double mismatch = 0.5) {
  return {{"technique", technique},
          {"work", work()},
          {"scene", "bunny"},
          {"size", {1280, 720}},
          {"shadow_map", 512},
          {"depth_format", "16"},
          {"params", json::object()},
          {"backend", "osmesa: llvmpipe"},
          {"timing", "wall"},
          {"gpu_ms", {{"total", 1.0}, {"passes", {{"visibility", 1.0}}}}},
          {"wall_ms", {{"total", wallMs}, {"passes", {{"visibility", wallMs}}}}},
          {"cpu_ms", wallMs},
          {"gbuffer_ms", 2.0},
          {"repeat", 1},
          {"triangles", 12},
          {"light",
           {{"type", "spot"}, {"eye", {0.0, 10.0, 0.0}}, {"near", 1.0}, {"far", 20.0}, {"fov", 45.0}, {"fitted", true},
            {"depth_step_world", {0.001, 0.01}}, {"texel_world", {0.01, 0.1}}}},
          {"memory_bytes", 524288},
          {"error",
           {{"mismatch_pct", mismatch},
            {"edge_mismatch_pct", 4.0},
            {"rmse", 0.03},
            {"leak_pct", 0.0},
            {"overestimation_pct", 0.0},
            {"boundary_px", {{"mean", 0.2}, {"p95", 1.0}}},
            {"soft_rmse", nullptr}}}};
}

// A run as `compare` writes it: the ground truth first, then sm, pcf and vsm.
json run() {
  json truth = record("groundtruth");
  truth["error"] = nullptr;  // references are skipped whatever they hold
  return json::array({truth, record("sm", 20.0, 0.1), record("pcf", 30.0, 0.2), record("vsm", 40.0, 0.6)});
}

struct Checked {
  std::vector<CheckRecord> baseline, current;
  CheckReport report;
};

Checked check(const json& baseline, const json& current, CheckTolerances tolerances = {}) {
  Checked c{parseCheckRecords(baseline, "base.json"), parseCheckRecords(current, "current.json"), {}};
  c.report = compareRecords(c.baseline, c.current, tolerances);
  return c;
}

// "technique metric" of every finding of `kind`, for readable expectations.
std::vector<std::string> findings(const Checked& c, FindingKind kind) {
  std::vector<std::string> out;
  for (const auto& f : c.report.findings)
    if (f.kind == kind)
      out.push_back(f.record->record.technique + " " +
                    (f.metric ? std::string(f.metric->name) : kind == FindingKind::New ? "new" : "missing"));
  return out;
}

using Names = std::vector<std::string>;

bool hasNote(const Checked& c, const std::string& part) {
  for (const auto& note : c.report.notes)
    if (note.find(part) != std::string::npos) return true;
  return false;
}

TEST(RegressionCheck, IdenticalRunsHaveNoFindings) {
  const Checked c = check(run(), run());
  EXPECT_TRUE(c.report.findings.empty());
  EXPECT_FALSE(c.report.failed());
  EXPECT_EQ(c.report.compared, 3);  // sm, pcf, vsm; not the ground truth
  EXPECT_NE(checkReportMarkdown(c.report, {}).find("**PASS**"), std::string::npos);
}

TEST(RegressionCheck, WorseMetricIsARegressionNamingIt) {
  json current = run();
  current[2]["error"]["boundary_px"]["mean"] = 0.3;
  const Checked c = check(run(), current);
  EXPECT_EQ(findings(c, FindingKind::Regression), Names{"pcf boundary_px.mean"});
  const std::string md = checkReportMarkdown(c.report, {});
  EXPECT_NE(md.find("bunny · pcf · 512²"), std::string::npos) << md;
  EXPECT_NE(md.find("boundary_px.mean 0.2 → 0.3 (+50.0%)"), std::string::npos) << md;
  EXPECT_NE(md.find("**FAIL**: 1 regression"), std::string::npos) << md;
}

TEST(RegressionCheck, BetterMetricIsAnImprovement) {
  json current = run();
  current[3]["error"]["mismatch_pct"] = 0.3;
  const Checked c = check(run(), current);
  EXPECT_EQ(findings(c, FindingKind::Improvement), Names{"vsm mismatch_pct"});
  EXPECT_FALSE(c.report.failed());
}

TEST(RegressionCheck, ChangesWithinToleranceAreNotReported) {
  json current = run();
  current[2]["error"]["mismatch_pct"] = 0.2 * 1.04;  // +4% < 5%
  current[2]["error"]["rmse"] = 0.03 * 1.2;           // +20% < 25%
  current[3]["wall_ms"]["total"] = 40.0 * 1.2;        // ratio +20% < 25%
  const Checked c = check(run(), current, {0.25, 0.25});
  EXPECT_TRUE(c.report.findings.empty()) << checkReportMarkdown(c.report, {});
}

TEST(RegressionCheck, NoiseOnAZeroBaselineStaysUnderTheFloor) {
  json current = run();
  current[2]["error"]["leak_pct"] = 0.005;  // baseline 0: any relative tolerance would fail
  current[2]["error"]["overestimation_pct"] = 0.009;
  EXPECT_TRUE(check(run(), current).report.findings.empty());
  current[2]["error"]["leak_pct"] = 0.02;  // above the 0.01-point floor
  EXPECT_EQ(findings(check(run(), current), FindingKind::Regression), Names{"pcf leak_pct"});
}

TEST(RegressionCheck, SoftRmseIsComparedOnlyWhenBothHaveIt) {
  json baseline = run(), current = run();
  current[2]["error"]["soft_rmse"] = 0.5;  // baseline has none: nothing to compare
  EXPECT_TRUE(check(baseline, current).report.findings.empty());
  baseline[2]["error"]["soft_rmse"] = 0.1;
  EXPECT_EQ(findings(check(baseline, current), FindingKind::Regression), Names{"pcf soft_rmse"});
}

TEST(RegressionCheck, SpeedIsTheRatioToSmInTheSameRun) {
  json current = run();
  for (auto& r : current) r["wall_ms"]["total"] = r["wall_ms"]["total"].get<double>() * 3;  // slower machine
  EXPECT_TRUE(check(run(), current).report.findings.empty());

  current = run();
  current[2]["wall_ms"]["total"] = 30.0 * 1.3;  // pcf: 1.5 → 1.95 × sm
  current[3]["wall_ms"]["total"] = 40.0 / 1.3;  // vsm: 2.0 → 1.54 × sm
  const Checked c = check(run(), current);
  EXPECT_EQ(findings(c, FindingKind::Regression), Names{"pcf x_sm"});
  EXPECT_EQ(findings(c, FindingKind::Improvement), Names{"vsm x_sm"});
}

TEST(RegressionCheck, TimingFieldPicksGpuOrWallTime) {
  json baseline = run(), current = run();
  for (auto* r : {&baseline, &current})
    for (auto& rec : *r) rec["timing"] = "gpu";  // gpu totals are all 1.0
  current[2]["wall_ms"]["total"] = 1000.0;       // ignored under gpu timing
  EXPECT_TRUE(check(baseline, current).report.findings.empty());
  current[2]["gpu_ms"]["total"] = 2.0;
  EXPECT_EQ(findings(check(baseline, current), FindingKind::Regression), Names{"pcf x_sm"});
}

TEST(RegressionCheck, DifferentBackendsSkipSpeedButCheckAccuracy) {
  json current = run();
  for (auto& r : current) r["backend"] = "egl: NVIDIA H100";
  current[2]["wall_ms"]["total"] = 300.0;
  current[2]["error"]["rmse"] = 0.1;
  const Checked c = check(run(), current);
  EXPECT_EQ(findings(c, FindingKind::Regression), Names{"pcf rmse"});
  ASSERT_EQ(c.report.notes.size(), 2u);  // speed and work, each once for the whole run
  EXPECT_TRUE(hasNote(c, "speed not compared: the backends differ"));
  EXPECT_TRUE(hasNote(c, "work not compared: the backends differ"));
  EXPECT_NE(checkReportMarkdown(c.report, {}).find("egl: NVIDIA H100"), std::string::npos);
}

TEST(RegressionCheck, DifferentShaderCompilersAreNamedAndStillCompared) {
  json current = run();
  for (auto& r : current) r["shader_path"] = "spirv";
  current[2]["error"]["rmse"] = 0.1;
  const Checked c = check(run(), current);  // the baseline predates the field: glsl
  EXPECT_EQ(findings(c, FindingKind::Regression), Names{"pcf rmse"});
  ASSERT_EQ(c.report.notes.size(), 1u);
  EXPECT_TRUE(hasNote(c, "shaders compiled by different front-ends (baseline glsl, current spirv)"));
  for (auto& r : current) r["shader_path"] = "glsl";
  EXPECT_TRUE(check(run(), current).report.notes.empty());
}

TEST(RegressionCheck, AnyMemoryIncreaseIsARegression) {
  json current = run();
  current[2]["memory_bytes"] = 524289;
  current[3]["memory_bytes"] = 262144;
  const Checked c = check(run(), current, {1.0, 1.0});  // tolerances do not apply to memory
  EXPECT_EQ(findings(c, FindingKind::Regression), Names{"pcf memory_bytes"});
  EXPECT_EQ(findings(c, FindingKind::Improvement), Names{"vsm memory_bytes"});
  EXPECT_NE(checkReportMarkdown(c.report, {}).find("memory_bytes 524288 → 524289 (+1 bytes)"), std::string::npos);
}

TEST(RegressionCheck, MissingRecordIsARegressionNewOneIsNot) {
  json current = run();
  current.erase(2);  // pcf
  json extra = record("esm", 25.0);
  current.push_back(extra);
  json otherMap = record("sm");
  otherMap["shadow_map"] = 1024;  // a different setup is a different record
  current.push_back(otherMap);
  const Checked c = check(run(), current);
  EXPECT_EQ(findings(c, FindingKind::Regression), Names{"pcf missing"});
  EXPECT_EQ(findings(c, FindingKind::New), (Names{"esm new", "sm new"}));
  EXPECT_TRUE(c.report.failed());

  current = run();
  current.push_back(extra);  // only a new record: listed, not a failure
  EXPECT_FALSE(check(run(), current).report.failed());
}

TEST(RegressionCheck, WorkCountersUnchangedPass) {
  const Checked c = check(run(), run());
  EXPECT_TRUE(c.report.findings.empty());
  EXPECT_TRUE(c.report.notes.empty()) << c.report.notes.front();
}

// The planted regression: pcf's shadow-map pass does 1 more fragment invocation than its
// baseline (a lowered baseline count) — with the default tolerance 0, any rise fails.
TEST(RegressionCheck, AnyRiseOfAWorkCounterInAnyPassFails) {
  json baseline = run();
  baseline[2]["work"]["passes"]["shadow-map"]["fragment_invocations"] = 999;
  const Checked c = check(baseline, run());
  EXPECT_TRUE(c.report.failed());
  EXPECT_EQ(findings(c, FindingKind::Regression), (Names{"pcf fragment_invocations"}));
  EXPECT_EQ(c.report.findings.front().pass, "shadow-map");
  const std::string md = checkReportMarkdown(c.report, {});
  EXPECT_NE(md.find("- bunny · pcf · 512² (1280×720, depth 16): pass `shadow-map` fragment_invocations 999 → 1000 (+0.1%)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("work tolerance 0%"), std::string::npos) << md;
  // Within a stated tolerance it passes; a fall is an improvement.
  EXPECT_FALSE(check(baseline, run(), {.work = 0.01}).report.failed());
  const Checked fewer = check(run(), baseline);
  EXPECT_FALSE(fewer.report.failed());
  EXPECT_EQ(findings(fewer, FindingKind::Improvement), (Names{"pcf fragment_invocations"}));
}

// A pass new in the current run counts from 0: its work is a rise.
TEST(RegressionCheck, ANewPassIsMoreWork) {
  json current = run();
  current[3]["work"]["passes"]["blur"] = current[3]["work"]["passes"]["visibility"];
  const Checked c = check(run(), current);
  EXPECT_EQ(findings(c, FindingKind::Regression).size(), kWorkCounters.size());
  EXPECT_EQ(c.report.findings.front().pass, "blur");
  EXPECT_EQ(c.report.findings.front().record->record.technique, "vsm");
}

// No counts is never zero counts: records without a work block, or from another backend,
// are not compared, and the report says why.
TEST(RegressionCheck, WorkIsNotComparedWithoutCountsOrAcrossBackends) {
  json current = run();
  current[2]["work"] = nullptr;
  const Checked missing = check(run(), current);
  EXPECT_FALSE(missing.report.failed());
  ASSERT_EQ(missing.report.notes.size(), 1u);
  EXPECT_NE(missing.report.notes[0].find("work not compared for records whose GL offered no pipeline statistics"),
            std::string::npos);

  json other = run();
  for (auto& r : other) {
    r["backend"] = "egl: NVIDIA";
    r["work"]["passes"]["visibility"]["vertex_invocations"] = 5000;
  }
  const Checked moved = check(run(), other);
  EXPECT_FALSE(moved.report.failed());
  EXPECT_TRUE(hasNote(moved, "another rasterizer counts other work"));

  json old = run();
  for (auto& r : old) r.erase("work");
  const Checked before = check(old, run());
  EXPECT_FALSE(before.report.failed());
  ASSERT_EQ(before.report.notes.size(), 1u);  // once, not once per record
  EXPECT_NE(before.report.notes[0].find("made before the work counters"), std::string::npos);
}

TEST(RegressionCheck, MalformedRecordsNameTheFileAndField) {
  auto message = [](const json& records) {
    return test::inputErrorOf([&] { parseCheckRecords(records, "runs/metrics.json"); }).value_or("accepted");
  };
  json r = run();
  r[2]["error"].erase("rmse");
  EXPECT_EQ(message(r), "runs/metrics.json: [2].error.rmse: missing required key");
  r = run();
  r[1].erase("backend");
  EXPECT_EQ(message(r), "runs/metrics.json: [1].backend: missing required key");
  r = run();
  r[3]["wall_ms"]["total"] = "fast";
  EXPECT_EQ(message(r), "runs/metrics.json: [3].wall_ms.total: expected a number, got \"fast\"");
  r = run();
  r[2]["timing"] = "cpu";
  EXPECT_EQ(message(r), "runs/metrics.json: [2].timing: expected \"gpu\" or \"wall\", got \"cpu\"");
  r = run();
  r[1]["light"].erase("near");
  EXPECT_EQ(message(r), "runs/metrics.json: [1].light.near: missing required key");
  r = run();
  r[1]["error"] = nullptr;
  EXPECT_EQ(message(r), "runs/metrics.json: [1].error: expected an object (records from `testbed compare`)");
  r = run();
  r[3]["memory_bytes"] = -1;
  EXPECT_EQ(message(r), "runs/metrics.json: [3].memory_bytes: expected a non-negative integer, got -1");
  EXPECT_NE(message(json::object()).find("expected a JSON array"), std::string::npos);
  r = run();
  r[1]["work"]["passes"]["visibility"].erase("compute_invocations");
  EXPECT_EQ(message(r), "runs/metrics.json: [1].work.passes.visibility.compute_invocations: missing required key");
  r = run();
  r[1]["work"]["total"]["vertex_invocations"] = -3;
  EXPECT_EQ(message(r), "runs/metrics.json: [1].work.total.vertex_invocations: expected a non-negative integer, got -3");
}

}  // namespace
}  // namespace testbed
