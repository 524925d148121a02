// `testbed conform` (docs/conformance.md): every in-tree technique passes every check (one
// test each, so a regression names its technique), the plugins of tests/conform_plugins/
// each fail on the line of the defect planted in them and pass the rest, the example plugins
// of tests/plugin_example/ pass every check, hostile plugins (exit, crash, abort, throw an
// int, hang) fail each check they take down, named with what happened, and bad input exits
// 2 before any check runs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "testbed/technique/registry.h"
#include "tests/cli_helpers.h"
#include "testbed_conform_plugins.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

using test::RunResult;
using test::runTestbed;

// The lines `conform` printed that start with `prefix` ("PASS ", "FAIL ").
std::vector<std::string> linesStartingWith(const std::string& out, const std::string& prefix) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < out.size()) {
    const std::size_t end = out.find('\n', start);
    const std::string line = out.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (line.rfind(prefix, 0) == 0) lines.push_back(line);
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return lines;
}

constexpr std::size_t kChecks = 9;

// SKIP: viewer-equals-render in a build without the viewer.
std::size_t passedOrSkipped(const std::string& out) {
  return linesStartingWith(out, "PASS ").size() + linesStartingWith(out, "SKIP ").size();
}

std::vector<std::string> inTreeIds() {
  std::vector<std::string> ids;
  for (const auto& t : registeredTechniques()) ids.push_back(t.info->id);
  return ids;
}

class ConformInTree : public ::testing::TestWithParam<std::string> {};

TEST_P(ConformInTree, PassesEveryCheck) {
  const RunResult run = runTestbed({"conform", "--technique", GetParam()});
  EXPECT_EQ(run.exitCode, 0) << run.describe() << "\n" << run.out;
  EXPECT_EQ(passedOrSkipped(run.out), kChecks) << run.out;
  EXPECT_TRUE(linesStartingWith(run.out, "FAIL ").empty()) << run.out;
}

INSTANTIATE_TEST_SUITE_P(Techniques, ConformInTree, ::testing::ValuesIn(inTreeIds()), [](const auto& info) {
  std::string name = info.param;
  for (char& c : name)
    if (c == '-') c = '_';
  return name;
});

// The example plugins of tests/plugin_example/ (the README's walk-through), loaded as users
// load them: every check passes, as for an in-tree technique.
struct ExamplePlugin {
  const char* path;
  std::string id;
};

class ConformExamplePlugin : public ::testing::TestWithParam<ExamplePlugin> {};

TEST_P(ConformExamplePlugin, PassesEveryCheck) {
  const RunResult run = runTestbed({"conform", "--plugin", GetParam().path, "--technique", GetParam().id});
  EXPECT_EQ(run.exitCode, 0) << run.describe() << "\n" << run.out;
  EXPECT_EQ(passedOrSkipped(run.out), kChecks) << run.out;
  EXPECT_TRUE(linesStartingWith(run.out, "FAIL ").empty()) << run.out;
}

INSTANTIATE_TEST_SUITE_P(Plugins, ConformExamplePlugin,
                         ::testing::Values(ExamplePlugin{TESTBED_PLUGIN_EXAMPLE, "example-sm"},
                                           ExamplePlugin{TESTBED_PLUGIN_PCSS, "pcss"},
                                           ExamplePlugin{TESTBED_PLUGIN_PSSM, "pssm"}),
                         [](const auto& info) {
                           std::string name = info.param.id;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

// A plugin with one defect: exit 1, FAIL on exactly the `failing` checks, PASS on the rest.
// A check this build skips (SKIP) is left out of `failing`.
void expectFailures(const char* plugin, const std::string& id, std::vector<std::string> failing) {
  const RunResult run = runTestbed({"conform", "--plugin", plugin, "--technique", id});
  for (const auto& skipped : linesStartingWith(run.out, "SKIP "))
    std::erase_if(failing, [&](const std::string& check) { return skipped.rfind("SKIP " + check + ":", 0) == 0; });
  EXPECT_EQ(run.exitCode, 1) << run.describe() << "\n" << run.out;
  const auto failures = linesStartingWith(run.out, "FAIL ");
  ASSERT_EQ(failures.size(), failing.size()) << run.out;
  for (std::size_t i = 0; i < failing.size(); ++i)
    EXPECT_EQ(failures[i].rfind("FAIL " + failing[i] + ":", 0), 0u) << failures[i];
  EXPECT_EQ(passedOrSkipped(run.out), kChecks - failing.size()) << run.out;
}

TEST(ConformDefects, NanAtAParameterExtremeFailsTheExtremes) {
  expectFailures(TESTBED_CONFORM_NAN_AT_EXTREME, "defect-nan-at-extreme", {"parameter-extremes"});
}

// The viewer's frame is a third run: it differs from render's as the two runs differ; so
// do the stability check's renders, far from any boundary.
TEST(ConformDefects, AFrameCounterInTheOutputFailsDeterminism) {
  expectFailures(TESTBED_CONFORM_NONDETERMINISTIC, "defect-nondeterministic",
                 {"viewer-equals-render", "determinism", "stability"});
}

TEST(ConformDefects, MemoryHiddenFromTheLedgerFailsTheLedger) {
  expectFailures(TESTBED_CONFORM_HIDDEN_MEMORY, "defect-hidden-memory", {"memory-ledger"});
}

TEST(ConformDefects, RawGlTexturesNeverFreedFailTheLedger) {
  expectFailures(TESTBED_CONFORM_RAW_TEXTURE_LEAK, "defect-raw-texture-leak", {"memory-ledger"});
}

TEST(ConformDefects, ADeclaredPassThatNeverRunsFailsDeclaredPasses) {
  expectFailures(TESTBED_CONFORM_UNRUN_PASS, "defect-unrun-pass", {"declared-passes"});
}

// The line of `check` in `out`, empty if none.
std::string lineOf(const std::string& out, const std::string& check) {
  for (const auto& prefix : {"PASS ", "FAIL ", "SKIP "})
    for (const auto& line : linesStartingWith(out, prefix))
      if (line.rfind(prefix + check + ":", 0) == 0) return line;
  return "";
}

// A plugin that takes its process down (or never returns) in every frame: exit 1 and every
// check that renders FAILs naming `fault`; the checks are each in a process of their own,
// so each one is reached and named.
void expectEveryRenderingCheckNames(const char* plugin, const std::string& id, const std::string& fault,
                                    std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"conform", "--plugin", plugin, "--technique", id};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult run = runTestbed(args);
  EXPECT_EQ(run.exitCode, 1) << run.describe() << "\n" << run.out;
  for (const char* check : {"parameter-extremes", "declared-passes", "facing", "light-frustum", "viewer-equals-render",
                            "determinism", "memory-ledger", "stability"}) {
    const std::string line = lineOf(run.out, check);
    if (line.rfind("SKIP ", 0) == 0) continue;
    EXPECT_EQ(line.rfind(std::string("FAIL ") + check + ":", 0), 0u) << check << "\n" << run.out;
    EXPECT_NE(line.find(fault), std::string::npos) << line;
  }
}

TEST(ConformHostile, ExitZeroIsAFailureNotAPass) {
  expectEveryRenderingCheckNames(TESTBED_CONFORM_EXIT_ZERO, "defect-exit-zero", "exited with status 0 before reporting");
}

TEST(ConformHostile, ASegfaultNamesTheCheckAndTheSignal) {
  expectEveryRenderingCheckNames(TESTBED_CONFORM_SEGFAULT, "defect-segfault", "killed by SIGSEGV");
}

TEST(ConformHostile, AnAbortNamesTheCheckAndTheSignal) {
  expectEveryRenderingCheckNames(TESTBED_CONFORM_ABORT, "defect-abort", "killed by SIGABRT");
}

TEST(ConformHostile, ThrowingAnIntIsNamed) {
  expectEveryRenderingCheckNames(TESTBED_CONFORM_THROW_INT, "defect-throw-int", "threw a non-std::exception");
}

// The plugin sleeps forever in its first frame: each check is killed at its limit.
TEST(ConformHostile, AnInfiniteLoopTimesOut) {
  expectEveryRenderingCheckNames(TESTBED_CONFORM_INFINITE_LOOP, "defect-infinite-loop", "timed out after 1 s",
                                 {"--check-timeout", "1"});
}

TEST(ConformBadInput, ExitsTwoWithOneLineAndNoCheck) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"conform", "--technique", "no-such-technique"},
        std::vector<std::string>{"conform", "--technique", "pcf", "--set", "kernel=4"},
        std::vector<std::string>{"conform", "--technique", "pcf", "--set", "no_such=1"},
        std::vector<std::string>{"conform", "--technique", "pcf", "--check-timeout", "0"},
        std::vector<std::string>{"conform", "--technique", "pcf", "--check-timeout", "nan"},
        std::vector<std::string>{"conform"}}) {
    const RunResult run = runTestbed(args);
    EXPECT_EQ(run.exitCode, 2) << run.describe();
    EXPECT_TRUE(linesStartingWith(run.out, "PASS ").empty() && linesStartingWith(run.out, "FAIL ").empty()) << run.out;
  }
}

}  // namespace
}  // namespace testbed
