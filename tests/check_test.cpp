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

}  // namespace
