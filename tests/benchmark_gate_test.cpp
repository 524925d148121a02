// The benchmark CI gate (README "Performance"): `compare` on every bundled scene at the
// small size of tests/baselines/settings, checked against the committed baselines in
// tests/baselines/<scene>/metrics.json. Accuracy (every error metric) and memory must be
// exactly the baseline's — llvmpipe is deterministic; `testbed check` then reports speed
// (the ratio to sm) without gating it, since CI machines differ. An intended change of
// output refreshes the baselines in the same commit: scripts/baselines.sh.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kSource = TESTBED_SOURCE_DIR;
const fs::path kBaselines = kSource / "tests" / "baselines";

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::vector<std::string> bundledScenes() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kSource / "scenes"))
    if (entry.path().extension() == ".json") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Runs a shell command; its exit status (-1 when it did not run).
int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const json* findRecord(const json& records, const std::string& technique) {
  for (const auto& record : records)
    if (record["technique"] == technique) return &record;
  return nullptr;
}

class BenchmarkGate : public testing::TestWithParam<std::string> {};

TEST_P(BenchmarkGate, AccuracyAndMemoryEqualTheBaseline) {
  const std::string scene = GetParam();
  const fs::path baseline = kBaselines / scene / "metrics.json";
  ASSERT_TRUE(fs::exists(baseline)) << baseline << " is missing: run scripts/baselines.sh";
  std::string settings = readText(kBaselines / "settings");
  settings.erase(settings.find_last_not_of(" \n") + 1);
  const fs::path out = fs::temp_directory_path() / ("testbed-gate-" + scene + "-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const std::string compare = std::string("timeout -k 5 600 '") + TESTBED_BINARY + "' compare --scene '" +
                              (kSource / "scenes" / (scene + ".json")).string() + "' " + settings + " --out '" +
                              out.string() + "' > /dev/null";
  ASSERT_EQ(run(compare), 0) << compare;

  const json expected = json::parse(readText(baseline));
  const json current = json::parse(readText(out / "metrics.json"));
  for (const auto& want : expected) {
    const std::string technique = want["technique"];
    const json* got = findRecord(current, technique);
    ASSERT_NE(got, nullptr) << technique << " is missing from the run";
    EXPECT_EQ((*got)["error"], want["error"]) << technique << ": accuracy differs from " << baseline;
    EXPECT_EQ((*got)["memory_bytes"], want["memory_bytes"]) << technique << ": memory differs from " << baseline;
  }
  EXPECT_EQ(current.size(), expected.size()) << "techniques were added or removed: run scripts/baselines.sh";

  // Speed is reported, never gated here: any ratio passes.
  const std::string check = std::string("'") + TESTBED_BINARY + "' check --baseline '" + baseline.string() +
                            "' --current '" + out.string() + "' --speed-tolerance 1e9 --out '" +
                            (out / "check.md").string() + "' > /dev/null";
  EXPECT_EQ(run(check), 0) << check;
  std::cout << readText(out / "check.md");
  fs::remove_all(out);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BenchmarkGate, testing::ValuesIn(bundledScenes()),
                         [](const testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
