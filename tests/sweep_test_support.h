#pragma once
// What the sweep, merge and Slurm tests share beyond tests/cli_helpers.h: the tiny spec,
// the cells of a set of records, and (tests/technique_gate.h) the gate that stops a sweep
// mid-run.
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli_helpers.h"
#include "tests/technique_gate.h"
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

}  // namespace testbed::test
