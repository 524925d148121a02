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

#include "testbed/harness/metric_table.h"
#include "testbed/harness/record.h"

namespace testbed {

// One technique's record and its speed against `sm` in the same file and setup. The
// metrics compared and how are the metric table's (harness/metric_table.h).
struct CheckRecord {
  std::string file;  // the metrics.json it came from, for messages
  Record record;
  std::optional<double> smRatio;  // the Speed metric (x_sm) against `sm`'s record
  bool smTimeZero = false;        // `sm`'s time in the same file and setup is 0: no ratio

  // scene, technique, screen size, shadow map, depth format: what records are matched by.
  std::string key() const;
};

// The records of one metrics.json array (a full record each, docs/record.md "The record"; an error
// block required). The references (groundtruth, area) are skipped.
// Throws InputError "<file>: [i].field: what" for a missing or mistyped field.
std::vector<CheckRecord> parseCheckRecords(const nlohmann::json& records, const std::string& file);

// `path`: a metrics.json, a folder holding one, or a folder whose sub-folders hold them
// (every metrics.json below it). `option` names the flag in errors. Throws InputError.
std::vector<CheckRecord> loadCheckRecords(const std::filesystem::path& path, const std::string& option);

struct CheckTolerances {
  double speed = 0.25;  // relative, on the ratio to `sm`
  double error = 0.05;  // relative, with an absolute floor per metric (Metric::floor)
  // Relative, per pass and work counter. 0: llvmpipe's counts repeat exactly across runs
  // and thread counts (docs/work-counters.md), so any rise is more work.
  double work = 0.0;
};

enum class FindingKind { Regression, Improvement, New };

struct Finding {
  FindingKind kind;
  const CheckRecord* record;  // the current one; the baseline's for a missing record
  const Metric* metric;       // null for a missing or a new record
  double baseline = 0, current = 0;
  std::string pass;  // a work counter's pass; empty for every other metric
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
