// `testbed worst` end to end (docs/corpus.md "Worst-case search"): bad input is one line
// and exit 2 with nothing written; on a scene family with a planted failure region (a
// drum under a sinking sun: shadow mapping's error grows as the sun grazes the floor) the
// search ends in that region; the scene files it writes reproduce, through `compare`,
// exactly the figures its manifest reports; the worst cases kept in tests/data/worst/
// still give their recorded figures.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/harness/metric_table.h"
#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path worstData() { return fs::path(TESTBED_TEST_DATA_DIR) / "worst"; }
fs::path family() { return worstData() / "drum_family.json"; }

const std::vector<std::string> kSmall = {"--size", "96x64", "--map-sizes", "128"};

// The technique's metric as `compare` reports it for a manifest's case.
double compareFigure(const json& manifest, const json& entry, const fs::path& folder, const fs::path& out) {
  // The manifest's command with the case's file and an output folder filled in.
  std::vector<std::string> args;
  std::istringstream words(entry.at("compare").get<std::string>());
  for (std::string word; words >> word;) args.push_back(word);
  EXPECT_EQ(args.front(), "testbed");
  args.erase(args.begin());
  for (std::size_t i = 0; i + 1 < args.size(); ++i) {
    if (args[i] == "--scene") args[i + 1] = (folder / args[i + 1]).string();
    if (args[i] == "--out") args[i + 1] = out.string();
  }
  const RunResult run = runTestbed(args);
  EXPECT_EQ(run.exitCode, 0) << run.describe();
  for (const auto& record : json::parse(readFile(out / "metrics.json")))
    if (record.at("technique") == manifest.at("technique"))
      return record.at("error").at(manifest.at("metric").get<std::string>()).get<double>();
  ADD_FAILURE() << "no record of " << manifest.at("technique");
  return NAN;
}

TEST(CliWorst, BadInputIsOneLineAndWritesNothing) {
  TempDir tmp("worst-bad");
  const std::string scene = family().string();
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"--scene", scene, "--technique", "sm", "--budget", "0"}, "--budget: 0 is outside 1.."},
      {{"--scene", scene, "--technique", "sm", "--budget", "2", "--k", "3"}, "--k: 3 is more than --budget 2"},
      {{"--scene", scene, "--technique", "sm", "--budget", "2", "--metric", "joules"}, "--metric: expected an error metric"},
      {{"--scene", scene, "--technique", "nosuch", "--budget", "2"}, "nosuch"},
      {{"--scene", (tmp / "missing.json").string(), "--technique", "sm", "--budget", "2"}, "missing.json: no such file"},
      {{"--scene", scene, "--technique", "sm", "--budget", "2", "--elevation", "50:10"}, "--elevation: expected MIN:MAX"},
      {{"--scene", scene, "--technique", "sm", "--budget", "2", "--map-sizes", "128,x"}, "--map-sizes: expected sizes"},
  };
  for (const auto& c : cases) {
    const RunResult run = runTestbed(with(with({"worst", "--out", (tmp / "out").string()}, c.args), {"--size", "96x64"}));
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(c.expected), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(tmp / "out"));
  }
}

// A camera whose far plane is just beyond its target: an orbit out to 1.5 times its
// distance would put the target beyond far, which the scene parser refuses (the search
// used to render 16 such configurations and then fail writing them). The search keeps
// every camera it moves within far, so all 16 configurations are written.
TEST(CliWorst, TheOrbitStaysWithinTheFarPlane) {
  TempDir tmp("worst-far");
  json scene = json::parse(readFile(family()));
  scene["camera"]["far"] = 90;  // the camera stands 83.2 from its target
  const fs::path file = writeFile(tmp / "near-far.json", scene.dump());
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed(
      with({"worst", "--scene", file.string(), "--technique", "sm", "--budget", "16", "--k", "16", "--out", out.string()},
           kSmall));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_NE(run.err.find("[16/16]"), std::string::npos) << run.err;
  const json manifest = json::parse(readFile(out / "manifest.json"));
  EXPECT_EQ(manifest.at("skipped"), 0);
  ASSERT_EQ(manifest.at("cases").size(), 16u);
  for (const auto& entry : manifest.at("cases")) {
    const json written = json::parse(readFile(out / entry.at("file").get<std::string>()));
    const json& camera = written.at("camera");
    double distance = 0;
    for (int i = 0; i < 3; ++i) distance += std::pow(camera["eye"][i].get<double>() - camera["target"][i].get<double>(), 2);
    EXPECT_LE(std::sqrt(distance), 0.95 * 90 + 1e-3) << written.dump();
  }
}

TEST(CliWorst, FindsThePlantedGrazingSunAndItsScenesReproduceTheFigures) {
  TempDir tmp("worst-planted");
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed(with({"worst", "--scene", family().string(), "--technique", "sm", "--budget", "12",
                                         "--k", "2", "--seed", "3", "--fixed-camera", "--out", out.string()},
                                        kSmall));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_NE(run.err.find("[12/12]"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("ETA"), std::string::npos) << run.err;
  const json manifest = json::parse(readFile(out / "manifest.json"));
  // The command that made it: the options given, in the order the command declares them.
  EXPECT_EQ(manifest.at("command"), "testbed worst --scene " + family().string() +
                                        " --technique sm --budget 12 --k 2 --seed 3 --map-sizes 128 --fixed-camera "
                                        "--size 96x64 --out " + out.string());
  const json& cases = manifest.at("cases");
  ASSERT_EQ(cases.size(), 2u);
  // The failure region: the sun within 20° of the floor (the range searched is 3°..85°).
  EXPECT_LT(cases[0].at("light_elevation_deg").get<double>(), 20.0) << manifest.dump(2);
  EXPECT_GE(cases[0].at("figure").get<double>(), cases[1].at("figure").get<double>());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(cases[i].at("figure"), cases[i].at("search_figure")) << "the written file renders as the searched scene";
    EXPECT_EQ(compareFigure(manifest, cases[i], out, tmp / ("compare" + std::to_string(i))),
              cases[i].at("figure").get<double>());
  }
}

// The worst cases found for in-tree techniques (docs/corpus.md "Worst-case search"),
// each folder one `testbed worst` run: every case still gives its figure, within what
// `check` calls noise (2 % or the metric's floor: another CPU's rasterizer may round an
// edge pixel apart).
TEST(CliWorst, RegressionScenesKeepTheirFigures) {
  TempDir tmp("worst-regression");
  std::size_t checked = 0;
  for (const auto& folder : fs::directory_iterator(worstData())) {
    if (!folder.is_directory()) continue;
    const json manifest = json::parse(readFile(folder.path() / "manifest.json"));
    for (const auto& entry : manifest.at("cases")) {
      SCOPED_TRACE(folder.path().filename().string() + "/" + entry.at("file").get<std::string>());
      const double figure = compareFigure(manifest, entry, folder.path(), tmp / std::to_string(checked++));
      const double recorded = entry.at("technique_value").get<double>();
      EXPECT_NEAR(figure, recorded, std::max(0.02 * recorded, metric(manifest.at("metric").get<std::string>()).floor));
    }
  }
  EXPECT_GE(checked, 2u);
}

}  // namespace
}  // namespace testbed::test
