#pragma once
// What the end-to-end tests share: temporary folders, small file helpers and running the
// real `testbed` binary as a subprocess (stdout through a pipe, stderr through a file, a
// time limit so that a hang fails the test instead of the suite).
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace testbed::cli {

namespace fs = std::filesystem;

inline std::string uniqueName(const std::string& prefix) {
  static std::atomic<unsigned> counter{0};
  static const unsigned salt = std::random_device{}();
  return prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(salt) + "-" + std::to_string(counter++);
}

// A fresh directory under the system temp folder, removed with everything in it.
class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / uniqueName("testbed-test")) { fs::create_directories(path_); }
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

inline void writeFile(const fs::path& file, const std::string& text) {
  if (file.has_parent_path()) fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  out << text;
  EXPECT_TRUE(out.flush()) << "cannot write " << file;
}

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
  int timeoutSeconds = 120;
};

// Runs the testbed binary through /bin/sh with `args`.
inline RunResult runTestbed(const std::vector<std::string>& args, const RunOptions& options = {}) {
  const fs::path errFile = fs::temp_directory_path() / uniqueName("testbed-stderr");
  std::string command;
  if (!options.cwd.empty()) command += "cd " + shellQuote(options.cwd.string()) + " && ";
  command += "exec env";
  // Appending piecewise (not `" " + quoted`) also keeps GCC 12's -Wrestrict false positive away.
  auto append = [&](const std::string& word) {
    command += ' ';
    command += shellQuote(word);
  };
  for (const auto& [name, value] : options.env) append(name + "=" + value);
  command += " timeout -k 5 " + std::to_string(options.timeoutSeconds);
  append(TESTBED_BINARY);
  for (const auto& arg : args) append(arg);

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

}  // namespace testbed::cli
