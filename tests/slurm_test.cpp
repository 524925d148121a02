// The sweep's job array on a real (single-node, localhost) Slurm cluster: the test writes
// the cluster's slurm.conf and munge key, starts munged, slurmctld and slurmd
// (scripts/slurm/local_cluster.sh), submits a 2-shard sweep with its dependent merge
// (scripts/slurm/submit.sh → sbatch --array=1-2), waits a bounded time, checks the merged
// records hold the same cells as a local run, and stops the daemons whatever happened.
#include <chrono>
#include <cstdlib>
#include <sstream>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/sweep_test_support.h"

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

TEST(Slurm, TwoShardJobArrayAndMergeHoldTheLocalRunsCells) {
  const std::string missing = missingTool({"munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo"});
  if (!missing.empty())
    GTEST_SKIP() << missing << " not installed: the Slurm test needs Debian's slurm-wlm and munge (scripts/setup.sh)";
  TempDir tmp("testbed-slurm");
  const LocalCluster cluster{tmp / "cluster"};
  const RunResult start = runCommand({(kSlurmScripts / "local_cluster.sh").string(), "start", cluster.dir.string()},
                                     {.timeoutSeconds = 60});
  ASSERT_EQ(start.exitCode, 0) << start.describe() << "\n" << readFile(cluster.dir / "slurmctld.log")
                               << readFile(cluster.dir / "slurmd.log");
  const RunOptions slurm = {.env = {{"SLURM_CONF", (cluster.dir / "slurm.conf").string()}, {"TESTBED_BINARY", TESTBED_BINARY}},
                            .timeoutSeconds = 60};
  const fs::path out = tmp / "sweep";
  const RunResult submit = runCommand({(kSlurmScripts / "submit.sh").string(), tinySpecFile().string(), out.string(), "2"}, slurm);
  ASSERT_EQ(submit.exitCode, 0) << submit.describe();
  std::istringstream ids(submit.out);
  std::string array, merge;
  ids >> array >> merge;
  ASSERT_FALSE(array.empty() || merge.empty()) << submit.out;

  // Bounded wait until neither job is queued or running.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
  bool done = false;
  while (!done && std::chrono::steady_clock::now() < deadline) {
    const RunResult queue = runCommand({"squeue", "-h", "-j", array + "," + merge}, {.env = slurm.env, .timeoutSeconds = 20});
    done = queue.exitCode == 0 && queue.out.find_first_not_of(" \n") == std::string::npos;
    if (!done) std::this_thread::sleep_for(std::chrono::milliseconds(500));
  }
  ASSERT_TRUE(done) << "the jobs did not finish within 180 s\n" << readFile(cluster.dir / "slurmctld.log");
  ASSERT_TRUE(fs::exists(out / "records.json")) << readFile(out / "logs" / "shard-1.log") << readFile(out / "logs" / "shard-2.log")
                                                << readFile(out / "logs" / "merge.log");
  EXPECT_NE(readFile(out / "logs" / "shard-1.log").find("shard 1/2"), std::string::npos);
  EXPECT_NE(readFile(out / "logs" / "shard-2.log").find("shard 2/2"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "tiny.md"));

  const RunResult local = runTestbed({"sweep", "--spec", tinySpecFile().string(), "--no-plot", "--out", (tmp / "local").string()});
  ASSERT_EQ(local.exitCode, 0) << local.describe();
  EXPECT_EQ(cellsOf(nlohmann::json::parse(readFile(out / "records.json"))),
            cellsOf(nlohmann::json::parse(readFile(tmp / "local" / "records.json"))));
}

}  // namespace
}  // namespace testbed::test
