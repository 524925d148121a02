// The sweep's job array on a real (single-node, localhost) Slurm cluster: the test writes
// the cluster's slurm.conf and munge key, starts munged, slurmctld and slurmd
// (scripts/slurm/local_cluster.sh), submits a 2-shard corpus study with its dependent
// merge (scripts/slurm/submit.sh → sbatch --array=1-2), cancels one shard while it is
// stopped at a gate (tests/gate_plugin), submits again, waits a bounded time, checks the
// merged records equal a local uninterrupted run's, and stops the daemons whatever happened.
#include <chrono>
#include <cstdlib>
#include <map>
#include <sstream>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/sweep_test_support.h"
#include "testbed_test_paths.h"

namespace testbed::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSlurmScripts = fs::path(TESTBED_SOURCE_DIR) / "scripts" / "slurm";

// The first of `tools` found neither on PATH nor in /usr/sbin, or "".
std::string missingTool(const std::vector<std::string>& tools) {
  for (const auto& tool : tools) {
    bool found = fs::exists("/usr/sbin/" + tool) || fs::exists("/usr/bin/" + tool);
    if (const char* path = std::getenv("PATH")) {
      std::stringstream dirs(path);
      for (std::string dir; !found && std::getline(dirs, dir, ':');) found = fs::exists(fs::path(dir) / tool);
    }
    if (!found) return tool;
  }
  return "";
}

// Stops the daemons when the test ends, however it ends.
struct LocalCluster {
  fs::path dir;
  ~LocalCluster() { runCommand({(kSlurmScripts / "local_cluster.sh").string(), "stop", dir.string()}, {.timeoutSeconds = 60}); }
};

// Bounded wait until none of `jobs` is queued or running (seconds 0: looks once). The bound
// only keeps a stuck cluster from hanging the test.
bool waitForJobs(const std::string& jobs, const RunOptions& slurm, int seconds) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
  for (;;) {
    const RunResult queue = runCommand({"squeue", "-h", "-j", jobs}, {.env = slurm.env, .timeoutSeconds = 20});
    if (queue.exitCode == 0 && queue.out.find_first_not_of(" \n") == std::string::npos) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
}

std::pair<std::string, std::string> submit(const fs::path& spec, const fs::path& out, const RunOptions& slurm) {
  const RunResult run = runCommand(
      {(kSlurmScripts / "submit.sh").string(), spec.string(), out.string(), "2", "--no-plot", "--plugin", TESTBED_GATE_PLUGIN}, slurm);
  EXPECT_EQ(run.exitCode, 0) << run.describe();
  std::istringstream ids(run.out);
  std::string array, merge;
  ids >> array >> merge;
  return {array, merge};
}

std::size_t finishedCells(const fs::path& shard) {
  std::size_t n = 0;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(shard / ".testbed-resume", error))
    n += entry.path().extension() == ".json" && entry.path().filename().string().rfind("cell-", 0) == 0;
  return n;
}

// A study over a generated corpus as a 2-task job array with its dependent merge; shard 1
// stops at the gate of its first test-gate cell, with the cells before it finished, and is
// cancelled there (scancel: SIGTERM), which cancels the merge; submitted again with the gate
// open, both shards skip the cells they finished and the merge holds the records of an
// uninterrupted local run.
TEST(Slurm, CorpusSweepKilledShardResumesAndMergesAsAnUninterruptedRun) {
  const std::string missing = missingTool({"munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo", "scancel"});
  if (!missing.empty())
    GTEST_SKIP() << missing << " not installed: the Slurm test needs Debian's slurm-wlm and munge (scripts/setup.sh)";
  TempDir tmp("testbed-slurm");
  const RunResult corpus = runTestbed({"corpus", "--seed", "2026", "--count", "2", "--out", (tmp / "corpus").string()});
  ASSERT_EQ(corpus.exitCode, 0) << corpus.describe();
  const nlohmann::json spec = {{"name", "corpus-study"}, {"scenes", (tmp / "corpus").string()},
                               {"settings", {{"size", "160x90"}}}, {"measure", "mismatch_pct"},
                               {"axes", {{"shadow_map", {16, 32, 64, 128, 256}}}}, {"techniques", {"sm", "pcf", "test-gate"}}};
  writeFile(tmp / "study.json", spec.dump());

  const LocalCluster cluster{tmp / "cluster"};
  const RunResult start = runCommand({(kSlurmScripts / "local_cluster.sh").string(), "start", cluster.dir.string()},
                                     {.timeoutSeconds = 120});
  ASSERT_EQ(start.exitCode, 0) << start.describe() << "\n" << readFile(cluster.dir / "slurmctld.log")
                               << readFile(cluster.dir / "slurmd.log");
  // The job array's tasks see the submitter's environment: the gate's folder, and a time
  // limit that ends a shard left waiting at the gate if the test cannot.
  TechniqueGate gate(tmp / "gate", "gate-1");  // shard 1's only: array task 1
  const RunOptions slurm = {.env = {{"SLURM_CONF", (cluster.dir / "slurm.conf").string()},
                                    {"TESTBED_BINARY", TESTBED_BINARY},
                                    {"TESTBED_TEST_GATE", (tmp / "gate").string()},
                                    {"SBATCH_OPTIONS", "--time=15"}},
                            .timeoutSeconds = 60};
  const fs::path out = tmp / "sweep", shard1 = out / "shards" / "1-of-2";
  const auto [array, merge] = submit(tmp / "study.json", out, slurm);
  ASSERT_FALSE(array.empty() || merge.empty());

  // Shard 1 cancelled at the gate: its cells before the first test-gate one are finished.
  ASSERT_TRUE(gate.waitUntilReached([&] { return waitForJobs(array + "_1", slurm, 0); }))
      << readFile(out / "logs" / "shard-1.log");
  const std::size_t left = finishedCells(shard1);
  ASSERT_GE(left, 1u) << readFile(out / "logs" / "shard-1.log");
  ASSERT_EQ(runCommand({"scancel", array + "_1"}, {.env = slurm.env, .timeoutSeconds = 20}).exitCode, 0);
  ASSERT_TRUE(waitForJobs(array + "," + merge, slurm, 180)) << readFile(cluster.dir / "slurmctld.log");
  ASSERT_FALSE(fs::exists(shard1 / "records.json")) << readFile(out / "logs" / "shard-1.log");
  ASSERT_FALSE(fs::exists(out / "records.json")) << "the merge ran although shard 1 was cancelled";
  EXPECT_EQ(finishedCells(shard1), left) << "shard 1 went past the gate";
  gate.open();

  // Submitted again: both shards resume, the merge runs.
  const auto [array2, merge2] = submit(tmp / "study.json", out, slurm);
  ASSERT_TRUE(waitForJobs(array2 + "," + merge2, slurm, 180)) << readFile(cluster.dir / "slurmctld.log");
  ASSERT_TRUE(fs::exists(out / "records.json")) << readFile(out / "logs" / "shard-1.log") << readFile(out / "logs" / "shard-2.log")
                                                << readFile(out / "logs" / "merge.log");
  const std::string log1 = readFile(out / "logs" / "shard-1.log"), log2 = readFile(out / "logs" / "shard-2.log");
  EXPECT_NE(log1.find("sweep: resuming: " + std::to_string(left) + " cells of shard 1/2"), std::string::npos) << log1;
  EXPECT_NE(log2.find("sweep: resuming: 16 cells of shard 2/2"), std::string::npos) << log2;  // all of them
  EXPECT_EQ(log2.find("] sm on"), std::string::npos) << log2;
  EXPECT_TRUE(fs::exists(out / "corpus-study.md"));

  const RunResult local = runTestbed({"sweep", "--spec", (tmp / "study.json").string(), "--plugin", TESTBED_GATE_PLUGIN,
                                      "--no-plot", "--out", (tmp / "local").string()});
  ASSERT_EQ(local.exitCode, 0) << local.describe();
  const nlohmann::json merged = nlohmann::json::parse(readFile(out / "records.json"));
  const nlohmann::json whole = nlohmann::json::parse(readFile(tmp / "local" / "records.json"));
  EXPECT_EQ(merged.size(), 32u);  // 2 scenes × (ground truth + 5 map sizes × 3 techniques)
  EXPECT_EQ(cellsOf(merged), cellsOf(whole));
  EXPECT_EQ(errorsOf(merged), errorsOf(whole));
}

}  // namespace
}  // namespace testbed::test
