// compare, sweep and worst measure through one loop (harness/measurement.h): the same
// scene, output size, map size and technique give the same error block whichever command
// measured it, the soft metrics included where both judge against the area-light reference.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string kSize = "160x90", kMap = "128", kAreaSamples = "8";

fs::path wallScene() { return fs::path(TESTBED_SOURCE_DIR) / "scenes" / "wall.json"; }

// One cell: pcf on the wall, judged against the hard and the area-light reference.
json oneCellSpec() {
  return {{"name", "one-cell"},
          {"scenes", {{"wall", wallScene().string()}}},
          {"settings",
           {{"size", kSize}, {"shadow_map", std::stoi(kMap)}, {"reference", "both"}, {"area_samples", std::stoi(kAreaSamples)}}},
          {"columns", {{{"label", kMap + "²"}}}},
          {"rows", {{{"label", "PCF"}, {"techniques", {"pcf"}}}}}};
}

const json& recordOf(const json& records, const std::string& technique) {
  for (const auto& r : records)
    if (r.at("technique") == technique) return r;
  throw std::runtime_error("no record of " + technique + " in " + records.dump());
}

TEST(MeasurementEquivalence, CompareAndAOneCellSweepGiveTheSameErrors) {
  TempDir tmp("measurement-equivalence");
  const RunResult compare =
      runTestbed({"compare", "--scene", wallScene().string(), "--techniques", "sm,pcf", "--size", kSize, "--shadow-map",
                  kMap, "--area-samples", kAreaSamples, "--out", (tmp / "compare").string()});
  ASSERT_EQ(compare.exitCode, 0) << compare.describe();
  writeFile(tmp / "spec.json", oneCellSpec().dump());
  const RunResult sweep =
      runTestbed({"sweep", "--spec", (tmp / "spec.json").string(), "--no-plot", "--out", (tmp / "sweep").string()});
  ASSERT_EQ(sweep.exitCode, 0) << sweep.describe();

  const json compared = json::parse(readFile(tmp / "compare" / "metrics.json"));
  const json swept = json::parse(readFile(tmp / "sweep" / "records.json"));
  for (const std::string technique : {"groundtruth", "pcf"}) {
    const json& a = recordOf(compared, technique).at("error");
    const json& b = recordOf(swept, technique).at("error");
    EXPECT_EQ(a, b) << technique << "\ncompare: " << a.dump() << "\nsweep: " << b.dump();
  }
  // Both judged pcf against the area light: the soft metrics are there to agree on.
  EXPECT_TRUE(recordOf(swept, "pcf").at("error").contains("soft_rmse")) << swept.dump();
}

// The same progress line in both: the step, what runs and where, the elapsed time and the ETA.
TEST(MeasurementEquivalence, CompareAndSweepReportProgressAlike) {
  TempDir tmp("measurement-progress");
  const RunResult compare = runTestbed({"compare", "--scene", wallScene().string(), "--techniques", "sm,pcf", "--size",
                                        kSize, "--shadow-map", kMap, "--out", (tmp / "compare").string()});
  ASSERT_EQ(compare.exitCode, 0) << compare.describe();
  writeFile(tmp / "spec.json", oneCellSpec().dump());
  const RunResult sweep =
      runTestbed({"sweep", "--spec", (tmp / "spec.json").string(), "--no-plot", "--out", (tmp / "sweep").string()});
  ASSERT_EQ(sweep.exitCode, 0) << sweep.describe();
  for (const RunResult* run : {&compare, &sweep}) {
    EXPECT_NE(run->err.find("[1/3] groundtruth on wall"), std::string::npos) << run->err;
    EXPECT_NE(run->err.find("[3/3] pcf on wall"), std::string::npos) << run->err;
    EXPECT_NE(run->err.find(", elapsed "), std::string::npos) << run->err;
    EXPECT_NE(run->err.find(", ETA "), std::string::npos) << run->err;
  }
}

}  // namespace
}  // namespace testbed::test
