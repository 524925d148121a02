#pragma once
// Helpers of the sweep, merge and Slurm tests: scratch folders, files, and the testbed
// binary (or any command) run through /bin/sh with a time limit.
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace testbed::test {

// A fresh folder under the system temp folder, removed with everything in it.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix) {
    static std::atomic<unsigned> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            (prefix + "-" + std::to_string(::getpid()) + "-" + std::to_string(std::random_device{}()) + "-" +
             std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

inline std::string readText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void writeText(const std::filesystem::path& file, const std::string& text) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << text;
}

inline std::string quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

struct CommandResult {
  int exitCode = -1;  // 124: ran past the time limit
  std::string out, err, command;
  std::string describe() const { return command + "\n  exit " + std::to_string(exitCode) + "\n  stderr: " + err; }
};

// Runs `words` (quoted) under `timeout`, stdout through a pipe, stderr via a temp file.
inline CommandResult runCommand(const std::vector<std::string>& words, int timeoutSeconds = 120, const std::string& env = "") {
  const ScratchDir errDir("testbed-stderr");
  CommandResult run;
  run.command = env + " timeout -k 5 " + std::to_string(timeoutSeconds);
  for (const auto& w : words) {
    run.command += ' ';
    run.command += quoted(w);
  }
  const std::string full = run.command + " 2>" + quoted((errDir / "err").string());
  FILE* pipe = ::popen(full.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) run.out.append(buffer, n);
  const int status = ::pclose(pipe);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = readText(errDir / "err");
  return run;
}

inline CommandResult runTestbed(std::vector<std::string> args) {
  args.insert(args.begin(), TESTBED_BINARY);
  return runCommand(args);
}

// tests/data/sweep_tiny.json: sm and pcf on the wall scene at 160×90, 64² and 128² maps.
inline std::filesystem::path tinySpecFile() { return std::filesystem::path(TESTBED_TEST_DATA_DIR) / "sweep_tiny.json"; }

// The cells a set of sweep records covers: what a merged and a whole run must agree on.
inline std::set<std::string> cellsOf(const nlohmann::json& records) {
  std::set<std::string> cells;
  for (const auto& r : records)
    cells.insert(r["cell"].dump() + " " + r["technique"].get<std::string>() + " " + r["scene"].get<std::string>() + " " +
                 r["size"].dump() + " " + r["shadow_map"].dump() + " " + r["params"].dump());
  return cells;
}

}  // namespace testbed::test
