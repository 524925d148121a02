#pragma once
// `testbed check`: compares two sets of `compare` records (metrics.json) and lists speed,
// accuracy and memory regressions. Pure data in, data out, so it is tested without the CLI.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace testbed {

// One technique's record, reduced to what the check compares.
struct CheckRecord {
  std::string file;  // the metrics.json it came from, for messages
  std::string scene, technique, depthFormat, backend, timing;
  int width = 0, height = 0, shadowMap = 0;
  double frameMs = 0;             // gpu_ms or wall_ms total, as `timing` says
  std::optional<double> smRatio;  // frameMs over `sm`'s in the same file and setup
  bool smTimeZero = false;        // `sm`'s time in the same file and setup is 0: no ratio
  std::uint64_t memoryBytes = 0;
  // The checked error metrics in report order; nullopt where the record has none (soft_rmse).
  std::vector<std::pair<std::string, std::optional<double>>> errors;

  // scene, technique, screen size, shadow map, depth format: what records are matched by.
  std::string key() const;
};

// The records of one metrics.json array. The references (groundtruth, area) are skipped.
// Throws InputError "<file>: [i].field: what" for a missing or mistyped field.
std::vector<CheckRecord> parseCheckRecords(const nlohmann::json& records, const std::string& file);

// `path`: a metrics.json, a folder holding one, or a folder whose sub-folders hold them
// (every metrics.json below it). `option` names the flag in errors. Throws InputError.
std::vector<CheckRecord> loadCheckRecords(const std::filesystem::path& path, const std::string& option);

struct CheckTolerances {
  double speed = 0.25;  // relative, on the ratio to `sm`
  double error = 0.05;  // relative, with an absolute floor per metric (errorFloor)
};

// The absolute slack under which a change of `metric` is noise (0.01 percentage points,
// 0.001 RMSE, 0.01 px).
double errorFloor(const std::string& metric);

enum class FindingKind { Regression, Improvement, New };

struct Finding {
  FindingKind kind;
  const CheckRecord* record;  // the current one; the baseline's for a missing record
  std::string metric;         // an error metric, "speed_ratio", "memory_bytes", "missing" or "new"
  double baseline = 0, current = 0;
};

struct CheckReport {
  std::vector<Finding> findings;
  std::vector<std::string> notes;  // what was not compared, and why
  int compared = 0;                // baseline records matched in current
  int count(FindingKind kind) const;
  bool failed() const { return count(FindingKind::Regression) > 0; }
};

// Findings point into `baseline` and `current`, which must outlive the report.
CheckReport compareRecords(const std::vector<CheckRecord>& baseline, const std::vector<CheckRecord>& current,
                           const CheckTolerances& tolerances);

// Markdown: one line per regression, improvement and new record, the notes, a summary line.
std::string checkReportMarkdown(const CheckReport& report, const CheckTolerances& tolerances);

}  // namespace testbed
