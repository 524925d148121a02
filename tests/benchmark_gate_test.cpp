// The benchmark CI gate (docs/benchmarks-and-check.md "The benchmark gate"): `compare` on every bundled scene at the
// small size of tests/baselines/settings, checked against the committed baselines in
// tests/baselines/<scene>/metrics.json. Accuracy (every error metric) and memory must be
// exactly the baseline's — llvmpipe is deterministic; `testbed check` then gates the work
// counters (no pass of any technique may count more than its baseline at the default
// --work-tolerance, docs/work-counters.md) and reports speed (the ratio to sm) without
// gating it, since wall times on shared CI machines move ±30 %. An intended change of output
// or work refreshes the baselines in the same commit: scripts/baselines.sh.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <sstream>
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

const fs::path kSource = TESTBED_SOURCE_DIR;
const fs::path kBaselines = kSource / "tests" / "baselines";

std::vector<std::string> bundledScenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kSource / "scenes"))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The words of tests/baselines/settings: the flags every gated run is made with.
std::vector<std::string> baselineSettings() {
  std::istringstream words(readFile(kBaselines / "settings"));
  return {std::istream_iterator<std::string>(words), std::istream_iterator<std::string>()};
}

const json* findRecord(const json& records, const std::string& technique) {
  for (const auto& record : records)
    if (record["technique"] == technique) return &record;
  return nullptr;
}

class BenchmarkGate : public testing::TestWithParam<std::string> {};

TEST_P(BenchmarkGate, AccuracyMemoryAndWorkHoldTheBaseline) {
  const std::string scene = GetParam();
  const fs::path baseline = kBaselines / scene / "metrics.json";
  ASSERT_TRUE(fs::exists(baseline)) << baseline << " is missing: run scripts/baselines.sh";
  const TempDir tmp("testbed-gate-" + scene);
  const fs::path out = tmp / "run";
  const RunResult compare =
      runTestbed(with({"compare", "--scene", (kSource / "scenes" / (scene + ".json")).string(), "--out", out.string()},
                      baselineSettings()),
                 {.timeoutSeconds = 600});
  ASSERT_EQ(compare.exitCode, 0) << compare.describe();

  const json expected = json::parse(readFile(baseline));
  const json current = json::parse(readFile(out / "metrics.json"));
  for (const auto& want : expected) {
    const std::string technique = want["technique"];
    const json* got = findRecord(current, technique);
    ASSERT_NE(got, nullptr) << technique << " is missing from the run";
    EXPECT_EQ((*got)["error"], want["error"]) << technique << ": accuracy differs from " << baseline;
    EXPECT_EQ((*got)["memory_bytes"], want["memory_bytes"]) << technique << ": memory differs from " << baseline;
  }
  EXPECT_EQ(current.size(), expected.size()) << "techniques were added or removed: run scripts/baselines.sh";

  // Work is gated at the default tolerance; speed is reported, never gated here: any ratio passes.
  const RunResult check = runTestbed({"check", "--baseline", baseline.string(), "--current", out.string(),
                                     "--speed-tolerance", "1e9", "--out", (out / "check.md").string()});
  EXPECT_EQ(check.exitCode, 0) << check.describe();
  const std::string report = readFile(out / "check.md");
  std::cout << report;
  EXPECT_EQ(report.find("work not compared"), std::string::npos) << "the baseline lacks work counts: run scripts/baselines.sh";

  // The planted regression: a baseline whose sm shadow-map pass counted one fragment fewer
  // than this run does. The gate must fail and name technique, pass, counter and counts.
  json planted = expected;
  json& sm = *const_cast<json*>(findRecord(planted, "sm"));
  ASSERT_TRUE(sm["work"].is_object()) << "llvmpipe offers ARB_pipeline_statistics_query: the baseline should count work";
  const std::uint64_t fragments = (*findRecord(current, "sm"))["work"]["passes"]["shadow-map"]["fragment_invocations"];
  sm["work"]["passes"]["shadow-map"]["fragment_invocations"] = fragments - 1;
  writeFile(tmp / "planted.json", planted.dump(2));
  const RunResult caught = runTestbed({"check", "--baseline", (tmp / "planted.json").string(), "--current",
                                      out.string(), "--speed-tolerance", "1e9"});
  EXPECT_EQ(caught.exitCode, 3) << caught.describe();
  const std::string finding = "pass `shadow-map` fragment_invocations " + std::to_string(fragments - 1) + " → " +
                              std::to_string(fragments);
  const auto at = caught.out.find(finding);
  ASSERT_NE(at, std::string::npos) << caught.describe();
  const auto lineStart = caught.out.rfind('\n', at) + 1;
  EXPECT_NE(caught.out.substr(lineStart, at - lineStart).find(" · sm · "), std::string::npos) << caught.describe();
}

INSTANTIATE_TEST_SUITE_P(Scenes, BenchmarkGate, testing::ValuesIn(bundledScenes()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
