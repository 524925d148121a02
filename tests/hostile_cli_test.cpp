// Hostile command lines: --out targets, options, `check` inputs and signals. Bad input
// gives exit 2, one stderr line and nothing written, before any rendering; outputs only
// ever replace regular files; an interrupted run leaves nothing of its own behind.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/sysmacros.h>
#include <sys/stat.h>

#include <string>
#include <functional>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli_helpers.h"
#include "tests/technique_gate.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;
using namespace testbed::test;
using nlohmann::json;

const std::string kWall = std::string(TESTBED_SOURCE_DIR) + "/scenes/wall.json";

std::vector<std::string> render(const std::string& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"render", "--scene", kWall, "--technique", "sm", "--size", "160x90",
                                   "--shadow-map", "128", "--out", out};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// --out targets that are not usable folders: refused before rendering (its one line is the
// error: no progress line, so no step started), nothing created.
TEST(HostileCli, BadOutFoldersAreRefusedBeforeRendering) {
  TempDir tmp;
  writeFile(tmp / "file", "x\n");
  for (const std::string& out : {std::string(""), (tmp / "file").string(), (tmp / "file" / "under").string(),
                                 std::string("/proc/testbed-x"), (tmp / std::string(300, 'a')).string(),
                                 (tmp / "new\nline" / std::string(300, 'b')).string()}) {
    SCOPED_TRACE(out);
    const RunResult run = runTestbed(render(out));
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find("--out"), std::string::npos) << run.err;
  }
  EXPECT_EQ(filesIn(tmp.path()), std::vector<std::string>{"file"});
  EXPECT_TRUE(fileHolds(tmp / "file", "x\n"));
}

// Output names held by a link, a FIFO, a folder or a device are never replaced or written
// through; the user's own sm.json.partial / sm.json.previous are never touched.
TEST(HostileCli, OutputsNeverReplaceOrFollowWhatIsNotARegularFile) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  writeFile(tmp / "victim", "precious\n");
  writeFile(out / "sm.json.partial", "mine\n");
  writeFile(out / "sm.json.previous", "mine too\n");
  struct Target {
    std::string name;
    std::function<void(const fs::path&)> make;
  };
  const std::vector<Target> targets = {
      {"symlink", [&](const fs::path& p) { fs::create_symlink(tmp / "victim", p); }},
      {"dangling symlink", [&](const fs::path& p) { fs::create_symlink(tmp / "nowhere", p); }},
      {"fifo", [](const fs::path& p) { ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0); }},
      {"folder", [](const fs::path& p) { fs::create_directory(p); }},
  };
  for (const auto& target : targets) {
    SCOPED_TRACE(target.name);
    target.make(out / "sm.json");
    const RunResult run = runTestbed(render(out.string()), {.cwd = {}, .env = {}, .timeoutSeconds = 30});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_EQ(filesIn(out), (std::vector<std::string>{"sm.json", "sm.json.partial", "sm.json.previous"}));
    std::error_code ec;
    fs::remove(out / "sm.json", ec);
  }
  EXPECT_TRUE(fileHolds(tmp / "victim", "precious\n"));
  // And a normal run beside the user's files leaves them as they were.
  const RunResult good = runTestbed(render(out.string()));
  ASSERT_EQ(good.exitCode, 0) << good.describe();
  EXPECT_EQ(filesIn(out), (std::vector<std::string>{"sm.exr", "sm.json", "sm.json.partial", "sm.json.previous",
                                                    "sm.png"}));
  EXPECT_TRUE(fileHolds(out / "sm.json.partial", "mine\n"));
  EXPECT_TRUE(fileHolds(out / "sm.json.previous", "mine too\n"));
}

// check --out: a device node (as root: /dev/null's twin), a link or a FIFO stays what it is.
TEST(HostileCli, CheckOutNeverReplacesANonRegularFile) {
  TempDir tmp;
  const std::string metrics = (kCommittedResults / "bunny-512" / "metrics.json").string();
  std::vector<fs::path> targets = {tmp / "link", tmp / "fifo"};
  fs::create_symlink(tmp / "victim", tmp / "link");
  writeFile(tmp / "victim", "precious\n");
  ASSERT_EQ(::mkfifo((tmp / "fifo").c_str(), 0600), 0);
  if (::mknod((tmp / "node").c_str(), S_IFCHR | 0600, makedev(1, 3)) == 0) targets.push_back(tmp / "node");
  for (const auto& target : targets) {
    SCOPED_TRACE(target.string());
    const RunResult run = runTestbed({"check", "--baseline", metrics, "--current", metrics, "--out", target.string()},
                                     {.cwd = {}, .env = {}, .timeoutSeconds = 30});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_TRUE(run.out.empty()) << "no report before the output is known to be writable";
    struct stat info {};
    ASSERT_EQ(::lstat(target.c_str(), &info), 0);
    EXPECT_FALSE(S_ISREG(info.st_mode));
  }
  EXPECT_TRUE(fileHolds(tmp / "victim", "precious\n"));
  EXPECT_EQ(filesIn(tmp.path()).size(), targets.size() + 1) << "no staging left";
}

TEST(HostileCli, OptionsAreValidated) {
  TempDir tmp;
  const std::vector<std::vector<std::string>> cases = {
      {"compare", "--scene", kWall, "--techniques", "pcf,"},
      {"compare", "--scene", kWall, "--techniques", ""},
      {"compare", "--scene", kWall, "--techniques", ",pcf"},
      {"compare", "--scene", kWall, "--techniques", "pcf,,vsm"},
      {"compare", "--scene", kWall, "--techniques", "sm", "--set", "vsm.blur=abc"},
      {"compare", "--scene", kWall, "--techniques", "sm", "--set", "vsm.nope=1"},
      {"compare", "--scene", kWall, "--techniques", "sm", "--set", ".blur=1"},
      {"compare", "--scene", kWall, "--size", "2x0"},
      {"compare", "--scene", kWall, "--area-samples", "-1"},
      {"render", "--scene", kWall, "--technique", "sm", "--size", "1x99999"},
      {"render", "--scene", kWall, "--technique", "sm", "--size", "x"},
      {"render", "--scene", kWall, "--technique", "sm", "--size", "-5x5"},
      {"render", "--scene", kWall, "--technique", "sm", "--size", "160x90x3"},
      {"render", "--scene", kWall, "--technique", "sm", "--repeat", "99999999999"},
      {"render", "--scene", kWall, "--technique", "sm", "--shadow-map", "-1"},
      {"render", "--scene", kWall, "--technique", "sm", "--set", "bias=1e999"},
      {"render", "--scene", kWall, "--technique", "sm", "--set", "=1"},
      {"render", "--scene", kWall, "--technique", "sm\nx"},
      {"groundtruth", "--scene", kWall, "--method", "guess"},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::vector<std::string> args = cases[i];
    const fs::path out = tmp / ("out-" + std::to_string(i));
    args.insert(args.end(), {"--out", out.string()});
    SCOPED_TRACE(args[3] + " " + args.back());
    const RunResult run = runTestbed(args);
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_FALSE(fs::exists(out));
  }
}

// check inputs: numbers beyond a double, negative measurements, files that are not files.
TEST(HostileCli, CheckInputsAreValidated) {
  TempDir tmp;
  const std::string good = (kCommittedResults / "bunny-512" / "metrics.json").string();
  const json records = json::parse(readFile(good));
  auto doctored = [&](const std::string& name, const std::function<void(json&)>& change) {
    json copy = records;
    change(copy);
    writeFile(tmp / name, copy.dump());
    return (tmp / name).string();
  };
  std::size_t pcf = 0;
  for (std::size_t i = 0; i < records.size(); ++i)
    if (records[i]["technique"] == "pcf") pcf = i;
  writeFile(tmp / "overflow.json", readFile(good).replace(readFile(good).find("\"cpu_ms\": "), 10, "\"cpu_ms\": 1e999, \"x\": "));
  ASSERT_EQ(::mkfifo((tmp / "fifo.json").c_str(), 0600), 0);
  writeFile(tmp / "deep.json", std::string(100000, '[') + std::string(100000, ']'));
  writeFile(tmp / "dup.json", "[{\"technique\": \"sm\", \"technique\": \"pcf\"}]");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {(tmp / "overflow.json").string(), "not a finite number"},
      {doctored("negative-time.json", [&](json& r) { r[pcf]["wall_ms"]["total"] = -1.0; r[pcf]["gpu_ms"]["total"] = -1.0; }),
       "total: expected a non-negative number"},
      {doctored("negative-metric.json", [&](json& r) { r[pcf]["error"]["rmse"] = -0.5; }), "rmse"},
      {doctored("negative-boundary.json", [&](json& r) { r[pcf]["error"]["boundary_px"]["mean"] = -2; }), "mean"},
      {(tmp / "fifo.json").string(), "FIFO"},
      {"/dev/zero", "device"},
      {(tmp / "deep.json").string(), "nested deeper"},
      {(tmp / "dup.json").string(), "twice"},
  };
  for (const auto& [current, says] : cases) {
    SCOPED_TRACE(current);
    const RunResult run = runTestbed({"check", "--baseline", good, "--current", current},
                                     {.cwd = {}, .env = {}, .timeoutSeconds = 20});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(says), std::string::npos) << run.err;
  }
  // A zero frame time is not a measurement: the speed check says it skipped, and why.
  const std::string zero = doctored("zero-time.json", [&](json& r) {
    r[pcf]["wall_ms"]["total"] = 0.0;
    r[pcf]["gpu_ms"]["total"] = 0.0;
  });
  const RunResult run = runTestbed({"check", "--baseline", good, "--current", zero});
  EXPECT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_NE(run.out.find("frame time is 0"), std::string::npos) << run.out;
}

// SIGTERM, SIGINT and the other catchable terminating signals (a closed pipe, Ctrl-\,
// a hang-up) mid-run: the staging folder and the output folder the run created are gone; earlier outputs in an existing folder stay as they were. SIGKILL cannot be
// caught: it leaves only the hidden staging folder, never a file a user could take for
// output.
TEST(HostileCli, InterruptedRunsLeaveNothingOfTheirOwn) {
  TempDir tmp;
  rlimit core{};  // SIGQUIT's default action dumps core: not here (the soft limit, inherited)
  ::getrlimit(RLIMIT_CORE, &core);
  core.rlim_cur = 0;
  ::setrlimit(RLIMIT_CORE, &core);
  writeFile(tmp / "existing" / "sm.json", "earlier\n");
  struct Case {
    int signal;
    fs::path out;
  };
  for (const Case& c : {Case{SIGTERM, tmp / "made" / "by" / "run"}, Case{SIGINT, tmp / "existing"},
                        Case{SIGQUIT, tmp / "quit" / "run"}, Case{SIGPIPE, tmp / "pipe" / "run"},
                        Case{SIGHUP, tmp / "hup" / "run"}, Case{SIGKILL, tmp / "killed"}}) {
    SCOPED_TRACE(strsignal(c.signal));
    // Stopped at the gate of its second technique (tests/technique_gate.h): the ground truth's
    // and sm's files are staged by then, the run is not finished.
    const fs::path gateFolder = tmp / ("gate-" + std::to_string(c.signal));
    TechniqueGate gate(gateFolder, "gate");
    BackgroundRun run({TESTBED_BINARY, "compare", "--scene", kWall, "--size", "160x90", "--shadow-map", "128",
                       "--techniques", "sm,test-gate", "--plugin", TESTBED_GATE_PLUGIN, "--out", c.out.string()},
                      {{"TESTBED_TEST_GATE", gateFolder.string()}}, gateFolder / "log");
    ASSERT_TRUE(gate.waitUntilReached([&] { return run.ended(); })) << readFile(gateFolder / "log");
    int staged = 0;
    for (const auto& name : filesIn(c.out))
      if (name.rfind(".testbed-staging-", 0) == 0) staged += int(filesIn(c.out / name).size());
    EXPECT_GE(staged, 6) << "groundtruth and sm: .png, .exr, .json each";
    const int status = run.stop(c.signal);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == c.signal) << "status " << status;
    if (c.signal != SIGINT && c.signal != SIGKILL) {
      EXPECT_FALSE(fs::exists(c.out.parent_path())) << "the folders it created are removed";
    } else if (c.signal == SIGINT) {
      EXPECT_EQ(filesIn(c.out), std::vector<std::string>{"sm.json"});
      EXPECT_TRUE(fileHolds(c.out / "sm.json", "earlier\n"));
    } else {
      const auto left = filesIn(c.out);
      ASSERT_EQ(left.size(), 1u);
      EXPECT_EQ(left[0].rfind(".testbed-staging-", 0), 0u) << left[0];
    }
  }
}

}  // namespace
