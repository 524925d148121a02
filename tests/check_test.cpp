// End-to-end tests of `testbed check` (docs/benchmarks-and-check.md "Regression check") on the committed
// results/: exit codes 0 / 3 / 2, what the report names, and --out. No GL: each run takes
// milliseconds.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;


using namespace testbed::test;

// `testbed check ARGS`.
RunResult check(const std::vector<std::string>& args, const TempDir&) {
  std::vector<std::string> all = {"check"};
  all.insert(all.end(), args.begin(), args.end());
  return runTestbed(all, {.cwd = {}, .env = {}, .timeoutSeconds = 60});
}

json bunny512() { return json::parse(readFile(kCommittedResults / "bunny-512" / "metrics.json")); }

std::size_t indexOf(const json& records, const std::string& technique) {
  for (std::size_t i = 0; i < records.size(); ++i)
    if (records[i]["technique"] == technique) return i;
  throw std::runtime_error("no " + technique + " record in results/bunny-512");
}

TEST(CliCheck, SameFolderPasses) {
  TempDir tmp;
  const RunResult r = check({"--baseline", (kCommittedResults / "bunny-512").string(), "--current",
                          (kCommittedResults / "bunny-512" / "metrics.json").string()},
                         tmp);
  EXPECT_EQ(r.exitCode, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("**PASS**: 0 regressions"), std::string::npos) << r.out;
}

TEST(CliCheck, EveryResultsFolderPasses) {
  TempDir tmp;
  const RunResult r = check({"--baseline", kCommittedResults.string(), "--current", kCommittedResults.string()}, tmp);
  EXPECT_EQ(r.exitCode, 0) << r.err << r.out;
  // 10 folders (5 scenes × 2 map sizes), every technique but the ground truth in each.
  EXPECT_NE(r.out.find("**PASS**: 0 regressions"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find(" 0 of "), std::string::npos) << r.out;  // records were compared
}

TEST(CliCheck, DoctoredRunExitsThreeNamingTechniqueAndMetric) {
  TempDir tmp;
  json records = bunny512();
  json& pcf = records[indexOf(records, "pcf")];
  pcf["error"]["edge_mismatch_pct"] = pcf["error"]["edge_mismatch_pct"].get<double>() * 1.5;
  writeFile(tmp / "run" / "metrics.json", records.dump(2));
  const fs::path report = tmp / "reports" / "check.md";
  const RunResult r = check({"--baseline", (kCommittedResults / "bunny-512").string(), "--current", (tmp / "run").string(),
                          "--out", report.string()},
                         tmp);
  EXPECT_EQ(r.exitCode, 3) << r.err << r.out;
  EXPECT_NE(r.out.find("bunny · pcf · 512²"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("edge_mismatch_pct"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("**FAIL**: 1 regression,"), std::string::npos) << r.out;
  EXPECT_EQ(readFile(report), r.out);
  EXPECT_FALSE(fs::exists(tmp / "reports" / "check.md.partial"));

  // The same change inside a generous tolerance passes.
  const RunResult loose = check({"--baseline", (kCommittedResults / "bunny-512").string(), "--current", (tmp / "run").string(),
                              "--error-tolerance", "0.6"},
                             tmp);
  EXPECT_EQ(loose.exitCode, 0) << loose.out;
}

TEST(CliCheck, BadInputExitsTwoNamingTheFile) {
  TempDir tmp;
  const std::string baseline = (kCommittedResults / "bunny-512").string();
  writeFile(tmp / "broken" / "metrics.json", "[{\"technique\": ");
  json records = bunny512();
  const std::size_t vsm = indexOf(records, "vsm");
  records[vsm]["error"].erase("leak_pct");
  writeFile(tmp / "nofield" / "metrics.json", records.dump());
  fs::create_directories(tmp / "empty");

  struct Case {
    std::vector<std::string> args;
    std::string expected;  // part of the one stderr line
  };
  const std::vector<Case> cases = {
      {{"--current", (tmp / "broken").string()}, (tmp / "broken" / "metrics.json").string() + ": line 1, column 16: JSON syntax error"},
      {{"--current", (tmp / "nofield").string()},
       (tmp / "nofield" / "metrics.json").string() + ": [" + std::to_string(vsm) + "].error.leak_pct: missing"},
      {{"--current", (tmp / "absent").string()}, "--current: " + (tmp / "absent").string() + ": no such file"},
      {{"--current", (tmp / "empty").string()}, "no metrics.json in it or below it"},
      {{"--current", baseline, "--speed-tolerance", "-0.1"}, "--speed-tolerance: expected a finite non-negative"},
      {{"--current", baseline, "--error-tolerance", "inf"}, "--error-tolerance: expected a finite non-negative"},
      {{"--current", baseline, "--work-tolerance", "-1"}, "--work-tolerance: expected a finite non-negative"},
      {{"--current", baseline, "--out", tmp.path().string()}, "--out: "},
  };
  for (const auto& c : cases) {
    std::vector<std::string> args = {"--baseline", baseline};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const RunResult r = check(args, tmp);
    EXPECT_EQ(r.exitCode, 2) << c.expected << "\n" << r.out;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

// Records of the paper path against records of the fast path: their passes and memory
// differ by design (docs/paths.md), so check refuses the pair in one line, as merge does,
// instead of reporting every fast-only pass as a regression.
TEST(CliCheck, RunsOfTwoPathsAreRefused) {
  TempDir tmp;
  json paper = bunny512(), fast = bunny512();
  for (auto& record : paper) record["path"] = "paper";
  for (auto& record : fast) record["path"] = "fast";
  writeFile(tmp / "paper" / "metrics.json", paper.dump());
  writeFile(tmp / "fast" / "metrics.json", fast.dump());
  const RunResult r = check({"--baseline", (tmp / "paper").string(), "--current", (tmp / "fast").string()}, tmp);
  EXPECT_EQ(r.exitCode, 2) << r.err << r.out;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("made on the fast path, the baseline's (" + (tmp / "paper" / "metrics.json").string() +
                       ") on the paper path"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out, "");
  // One path on both sides compares as before.
  const RunResult same = check({"--baseline", (tmp / "paper").string(), "--current", (tmp / "paper").string()}, tmp);
  EXPECT_EQ(same.exitCode, 0) << same.err << same.out;
}

// A pass name, scene or backend read from a record is text, not Markdown: a line break,
// '#', '|', backticks or HTML in it stay inside the finding's line and read as themselves.
TEST(CliCheck, TextFromRecordsCannotBreakTheReport) {
  TempDir tmp;
  const std::string pass = "p\n# Injected heading | `x` <img src=x>";
  json baseline = bunny512();
  for (auto& record : baseline) {
    record["scene"] = "bunny\n# scene";
    if (!record["work"].is_object() || !record["work"]["passes"].contains("visibility")) continue;
    json& passes = record["work"]["passes"];
    passes[pass] = passes["visibility"];
    passes.erase("visibility");
  }
  json current = baseline;
  json& work = current[indexOf(current, "pcf")]["work"];
  for (auto& [counter, count] : work["passes"][pass].items()) {
    const std::uint64_t more = count.get<std::uint64_t>() * 2 + 1000;  // beyond any tolerance
    count = count.get<std::uint64_t>() + more;
    work["total"][counter] = work["total"][counter].get<std::uint64_t>() + more;
  }
  writeFile(tmp / "baseline" / "metrics.json", baseline.dump());
  writeFile(tmp / "current" / "metrics.json", current.dump());
  const RunResult r = check({"--baseline", (tmp / "baseline").string(), "--current", (tmp / "current").string()}, tmp);
  EXPECT_EQ(r.exitCode, 3) << r.err << r.out;
  EXPECT_NE(r.out.find("- bunny<br># scene · pcf · 512²"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("pass ``p # Injected heading \\| `x` <img src=x>`` "), std::string::npos) << r.out;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind("#", 0) == 0)
      EXPECT_TRUE(line == "# Regression check" || line.rfind("## ", 0) == 0) << line;
}

}  // namespace
