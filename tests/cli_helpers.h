#pragma once
// What the tests share: scratch folders, small file helpers, and running the real
// `testbed` binary (or any command) as a subprocess (stdout through a pipe, stderr through
// a file, a time limit so that a hang fails the test instead of the suite).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed_test_paths.h"

namespace testbed::test {

namespace fs = std::filesystem;

// Unique across the processes ctest runs in parallel and across the calls of one.
// The results the repository commits (results/): check and merge tests read them as baselines.
inline const fs::path kCommittedResults = fs::path(TESTBED_SOURCE_DIR) / "results";

inline std::string uniqueName(const std::string& prefix) {
  static std::atomic<unsigned> counter{0};
  static const unsigned salt = std::random_device{}();
  return prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(salt) + "-" + std::to_string(counter++);
}

// A fresh directory under the system temp folder, removed with everything in it.
class TempDir {
 public:
  explicit TempDir(const std::string& prefix = "testbed-test") : path_(fs::temp_directory_path() / uniqueName(prefix)) {
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

// Writes `text` to `file`, making its folders first; returns the file.
inline fs::path writeFile(const fs::path& file, const std::string& text) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  EXPECT_TRUE(out.flush()) << "cannot write " << file;
  return file;
}

// The whole file; empty when it cannot be read.
inline std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Names of the entries directly inside `dir`, sorted; empty when it does not exist.
inline std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> names;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

inline std::string shellQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

struct RunResult {
  int exitCode = -1;  // the process's exit status; 124 when it ran past the time limit
  std::string out, err;
  std::string command;  // for failure messages

  // The command, its exit code and stderr: printed by assertions so a failure shows what happened.
  std::string describe() const { return command + "\n  exit " + std::to_string(exitCode) + "\n  stderr: " + err; }
};

struct RunOptions {
  fs::path cwd;                                          // empty: the test's own
  std::vector<std::pair<std::string, std::string>> env;  // added to the environment
  std::vector<std::string> unset;                        // removed from it (`env -u`)
  int timeoutSeconds = 120;
};

// Runs `words` (the program, then its arguments) through /bin/sh, stdin from /dev/null.
inline RunResult runCommand(const std::vector<std::string>& words, const RunOptions& options = {}) {
  const fs::path errFile = fs::temp_directory_path() / uniqueName("testbed-stderr");
  std::string command;
  if (!options.cwd.empty()) command += "cd " + shellQuote(options.cwd.string()) + " && ";
  command += "exec env";
  // Appending piecewise (not `" " + quoted`) also keeps GCC 12's -Wrestrict false positive away.
  auto append = [&](const std::string& word) {
    command += ' ';
    command += shellQuote(word);
  };
  for (const auto& name : options.unset) {
    command += " -u";
    append(name);
  }
  for (const auto& [name, value] : options.env) append(name + "=" + value);
  command += " timeout -k 5 " + std::to_string(options.timeoutSeconds);
  for (const auto& word : words) append(word);

  RunResult result;
  result.command = command;
  command += " </dev/null 2>";
  command += shellQuote(errFile.string());
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) {
    ADD_FAILURE() << "popen failed for " << command;
    return result;
  }
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) result.out.append(buffer, n);
  const int status = ::pclose(pipe);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.err = readFile(errFile);
  std::error_code ignored;
  fs::remove(errFile, ignored);
  return result;
}

// Runs the testbed binary with `args`.
inline RunResult runTestbed(std::vector<std::string> args, const RunOptions& options = {}) {
  args.insert(args.begin(), TESTBED_BINARY);
  return runCommand(args, options);
}

// `args` followed by `more`: common flags appended to a command line.
inline std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The message of the InputError `action` throws; nothing, and a test failure, when it
// throws none.
template <typename Action>
std::optional<std::string> inputErrorOf(Action&& action) {
  try {
    action();
  } catch (const InputError& error) {
    return std::string(error.what());
  }
  ADD_FAILURE() << "accepted: expected an InputError";
  return std::nullopt;
}

// Compares without printing the file: on failure it may hold a whole PNG.
inline ::testing::AssertionResult fileHolds(const fs::path& file, const std::string& expected) {
  if (!fs::is_regular_file(file)) return ::testing::AssertionFailure() << file << " is not a regular file";
  const std::string actual = readFile(file);
  if (actual == expected) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << file << " was changed: it now holds " << actual.size() << " bytes";
}

// The bad-input contract: exit 2 and exactly one non-empty line on stderr, "testbed: ...".
inline ::testing::AssertionResult rejectedWithOneLine(const RunResult& run) {
  const bool oneLine = run.err.size() > 1 && std::count(run.err.begin(), run.err.end(), '\n') == 1 &&
                       run.err.back() == '\n' && run.err.rfind("testbed: ", 0) == 0;
  if (run.exitCode == 2 && oneLine) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "expected exit 2 and one line\n" << run.describe();
}

}  // namespace testbed::test
