// The private temporary folders of `compare --frames` (testbed-motion-*: videos, series,
// plots) and of `sweep` (testbed-plot-*) are removed on a caught signal as the staging
// folder is (io/interrupt_cleanup.h), and a write into them that fails names the file
// rather than leave a truncated file for matplotlib (app/work_folder.h).
//
// The signal is sent by the plot script itself ($TESTBED_PYTHON, a shell script that
// signals its parent), so it lands at a known point, with every video and series written.
#include <signal.h>
#include <sys/resource.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "testbed/app/work_folder.h"
#include "tests/cli_helpers.h"
#include "tests/sweep_test_support.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;
using namespace testbed::test;

// A "python" that, run on a plot script, signals the testbed running it.
fs::path signallingPython(const fs::path& folder, const char* signal) {
  const fs::path script = folder / "python";
  writeFile(script, std::string("#!/bin/sh\nkill -") + signal + " $PPID\nexit 1\n");
  fs::permissions(script, fs::perms::owner_all);
  return script;
}

struct SignalledRun {
  std::vector<std::string> args;
  const char* leftover;  // the temporary folder's prefix
};

TEST(TemporaryFolders, ACaughtSignalRemovesThem) {
  const std::string animated = std::string(TESTBED_SOURCE_DIR) + "/scenes/motion/spinning_occluder.json";
  for (const char* signal : {"TERM", "INT", "HUP"}) {
    SCOPED_TRACE(signal);
    TempDir tmp;
    fs::create_directories(tmp / "tmp");
    const fs::path python = signallingPython(tmp.path(), signal);
    for (const SignalledRun& run :
         {SignalledRun{{"compare", "--scene", animated, "--techniques", "sm", "--frames", "0:2", "--size", "96x64",
                        "--shadow-map", "128", "--out", (tmp / "motion").string()},
                       "testbed-motion-"},
          SignalledRun{{"sweep", "--spec", tinySpecFile().string(), "--out", (tmp / "sweep").string()}, "testbed-plot-"}}) {
      SCOPED_TRACE(run.args.front());
      const RunResult result = runTestbed(
          run.args, {.cwd = {}, .env = {{"TMPDIR", (tmp / "tmp").string()}, {"TESTBED_PYTHON", python.string()}}});
      EXPECT_NE(result.exitCode, 0) << result.describe();
      EXPECT_EQ(filesIn(tmp / "tmp"), std::vector<std::string>{}) << "nothing left in $TMPDIR (" << run.leftover << "*)";
    }
  }
}

// A full disk, as a file-size limit: the write fails with its file named.
TEST(TemporaryFolders, AFailedWriteNamesTheFile) {
  struct sigaction ignore {}, previous {};
  ignore.sa_handler = SIG_IGN;
  ::sigaction(SIGXFSZ, &ignore, &previous);  // EFBIG instead of the signal
  rlimit limit{}, saved{};
  ::getrlimit(RLIMIT_FSIZE, &saved);
  limit = saved;
  limit.rlim_cur = 1000;
  ::setrlimit(RLIMIT_FSIZE, &limit);
  std::string message;
  fs::path folder;
  {
    const testbed::WorkFolder work("testbed-write-test");
    folder = work.path();
    try {
      work.write("series.json", std::string(5000, 'x'));
    } catch (const std::runtime_error& error) {
      message = error.what();
    }
  }
  ::setrlimit(RLIMIT_FSIZE, &saved);
  ::sigaction(SIGXFSZ, &previous, nullptr);
  EXPECT_EQ(message.rfind((folder / "series.json").string() + ": write failed: ", 0), 0u) << message;
  EXPECT_FALSE(fs::exists(folder));
}

}  // namespace
