// Plugins that misbehave inside `compare` (tests/conform_plugins/): a visibility outside
// [0, 1] (+inf, 2, -1) is refused as NaN is, naming the technique, the pixel and the value,
// with or without --frames (never blamed on matplotlib), and nothing is written; a plugin
// that crashes (SIGSEGV, abort) leaves no staging folder and no folder the run created,
// and the outputs of an earlier run stay as they were (io/interrupt_cleanup.h).
#include <sys/resource.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli_helpers.h"
#include "testbed_conform_plugins.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;
using namespace testbed::test;

const std::string kWall = std::string(TESTBED_SOURCE_DIR) + "/scenes/wall.json";
const std::string kAnimated = std::string(TESTBED_SOURCE_DIR) + "/scenes/motion/spinning_occluder.json";
const std::vector<std::string> kSmall = {"--size", "96x64", "--shadow-map", "128"};

struct BadValue {
  const char* plugin;
  std::string id, value;
};

const BadValue kBadValues[] = {{TESTBED_CONFORM_INF_VISIBILITY, "defect-inf-visibility", "inf"},
                               {TESTBED_CONFORM_TWO_VISIBILITY, "defect-two-visibility", "2"},
                               {TESTBED_CONFORM_NEGATIVE_VISIBILITY, "defect-negative-visibility", "-1"}};

TEST(HostilePlugin, VisibilityOutsideTheUnitRangeIsRefusedNamingTechniquePixelAndValue) {
  for (const BadValue& bad : kBadValues) {
    SCOPED_TRACE(bad.id);
    TempDir tmp;
    const fs::path out = tmp / "out";
    const RunResult run = runTestbed(with({"compare", "--plugin", bad.plugin, "--techniques", bad.id, "--scene", kWall,
                                           "--out", out.string()},
                                          kSmall));
    EXPECT_EQ(run.exitCode, 1) << run.describe();
    EXPECT_NE(run.err.find("technique " + bad.id + ": "), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("visibility is " + bad.value + " at pixel ("), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out)) << "nothing is written";
  }
}

TEST(HostilePlugin, WithFramesTheBadValueIsNamedNotMatplotlib) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  const RunResult run = runTestbed(with({"compare", "--plugin", TESTBED_CONFORM_INF_VISIBILITY, "--techniques",
                                         "defect-inf-visibility", "--scene", kAnimated, "--frames", "0:2",
                                         "--out", out.string()},
                                        kSmall));
  EXPECT_EQ(run.exitCode, 1) << run.describe();
  EXPECT_NE(run.err.find("defect-inf-visibility at frame 0: "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("visibility is inf at pixel ("), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find("matplotlib"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out)) << "nothing is written";
}

TEST(HostilePlugin, ACrashingPluginLeavesNoStagingFolder) {
  rlimit core{};  // a crash's default action dumps core: not here (the soft limit, inherited)
  ::getrlimit(RLIMIT_CORE, &core);
  core.rlim_cur = 0;
  ::setrlimit(RLIMIT_CORE, &core);
  struct Crash {
    const char* plugin;
    std::string id;
  };
  for (const Crash& crash : {Crash{TESTBED_CONFORM_SEGFAULT, "defect-segfault"}, Crash{TESTBED_CONFORM_ABORT, "defect-abort"}}) {
    SCOPED_TRACE(crash.id);
    TempDir tmp;
    writeFile(tmp / "existing" / "sm.json", "earlier\n");
    for (const fs::path& out : {tmp / "made" / "by" / "run", tmp / "existing"}) {
      SCOPED_TRACE(out.string());
      const RunResult run = runTestbed(with({"compare", "--plugin", crash.plugin, "--techniques", "sm," + crash.id,
                                             "--scene", kWall, "--out", out.string()},
                                            kSmall));
      EXPECT_NE(run.exitCode, 0) << run.describe();
      EXPECT_EQ(run.err.find("testbed: wrote"), std::string::npos) << run.err;
    }
    EXPECT_FALSE(fs::exists(tmp / "made")) << "the folders the run created are removed";
    EXPECT_EQ(filesIn(tmp / "existing"), std::vector<std::string>{"sm.json"});
    EXPECT_TRUE(fileHolds(tmp / "existing" / "sm.json", "earlier\n"));
  }
}

}  // namespace
