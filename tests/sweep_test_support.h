#pragma once
// What the sweep, merge and Slurm tests share beyond tests/cli_helpers.h: the tiny spec,
// the cells of a set of records and the gate that stops a sweep mid-run.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace testbed::test {

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

// The records' cells and error blocks: what a resumed or merged run and an uninterrupted one
// must agree on (times differ run to run, errors do not).
inline std::map<std::string, nlohmann::json> errorsOf(const nlohmann::json& records) {
  std::map<std::string, nlohmann::json> out;
  for (const auto& r : records) out[r["cell"].dump() + " " + r["technique"].get<std::string>()] = r["error"];
  return out;
}

// A gate of tests/gate_plugin/gate_plugin.cpp: the FIFO `name` in `folder`. A sweep run with
// `--plugin TESTBED_GATE_PLUGIN`, the technique `test-gate` in its spec and
// TESTBED_TEST_GATE=folder in its environment stops there before its first test-gate frame,
// every cell it ran before finished, until it is killed. A test that fails before killing it
// lets it go (the destructor), so no process is left waiting.
class SweepGate {
 public:
  SweepGate(const std::filesystem::path& folder, const std::string& name) : fifo_(folder / name) {
    std::filesystem::create_directories(folder);
    if (::mkfifo(fifo_.c_str(), 0600) != 0) throw std::runtime_error("mkfifo failed: " + fifo_.string());
  }
  SweepGate(const SweepGate&) = delete;
  SweepGate& operator=(const SweepGate&) = delete;
  ~SweepGate() { open(); }

  // Written by the process as it stops at the gate.
  std::filesystem::path reached() const { return fifo_.string() + ".reached"; }

  // True once a process stopped at the gate. The process always gets there unless it fails,
  // so the bound only keeps a broken run from hanging the test, and `ended()` (checked between
  // looks) stops the wait at once when the process is gone without reaching it.
  bool waitUntilReached(const std::function<bool()>& ended, int seconds = 300) const {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(seconds);
    while (!std::filesystem::exists(reached())) {
      if (ended() && !std::filesystem::exists(reached())) return false;
      if (std::chrono::steady_clock::now() > deadline) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return true;
  }

  // Opens the gate for good: a process waiting there goes on, later ones pass.
  void open() {
    const int fd = ::open(fifo_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);  // ENXIO when none waits
    if (fd >= 0) ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(fifo_, ignored);
  }

 private:
  std::filesystem::path fifo_;
};

}  // namespace testbed::test
