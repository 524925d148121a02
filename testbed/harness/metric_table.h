#pragma once
// The one list of what a record measures: every stored figure (its JSON path in the
// record) and every figure derived from one (ratios to `sm`, the whole frame, fps, memory
// in KiB or MB), with how tables print it, how `check` judges it and which way is better.
// The record writer and reader, report.md, grid.png, `check`, the sweep tables, the
// benchmarks' counters and, through `testbed metrics --json`, the Python scripts all read
// it; no other place names a metric.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace testbed {

struct Record;

enum class Better { Lower, Higher };

// How `check` compares a metric between a baseline and a current record.
enum class CheckRule {
  None,
  Error,  // regresses beyond max(--error-tolerance × baseline, floor)
  Speed,  // a ratio to sm: regresses beyond baseline × (1 + --speed-tolerance)
  Exact,  // any change counts (memory is counted exactly by the GL wrappers)
  Work,   // a work counter: each pass's count regresses beyond baseline × (1 + --work-tolerance)
};

// Where a metric is shown (bit flags).
enum MetricUse : unsigned {
  kReportColumn = 1,   // a column of report.md, in table order
  kBrief = 2,          // the one-line summary of grid.png's rows and the progress lines
  kCounter = 4,        // a counter of testbed_benchmarks
  kSweepMeasure = 8,   // a spec's "measure" (docs/paper-runs.md "Spec")
  // A derived figure the record carries in its "derived" block, computed here once so
  // that no reader (the Python scripts above all) derives it again.
  kCarried = 16,
};

// What an error metric was measured against (docs/ground-truth-and-metrics.md): the
// point-light ground truth, the area-light reference, or neither (times, memory, work).
enum class MetricReference { None, Hard, Soft };
std::string_view referenceName(MetricReference reference);  // "", "hard", "soft"

struct Metric {
  std::string_view name;     // as check's findings, the benchmarks and the README name it
  std::string_view path;     // JSON pointer into a record; empty for a derived figure
  std::string_view heading;  // report.md column heading
  std::string_view brief;    // label in the one-line summary (may be empty)
  std::string_view suffix;   // written after a value: " ms", "%", "x sm"
  int digits;                // decimals in report.md and the sweep tables
  CheckRule check;
  double floor;  // CheckRule::Error: the absolute change under which it is noise
  Better better;
  unsigned uses;  // MetricUse flags
  bool integer;   // stored as a JSON integer (memory_bytes)
  // Stored as null where absent (soft_rmse without an area reference); a metric that is
  // not nullable and has no value has no key (the penumbra metrics without a reference).
  bool nullable;
  // The value in `record`; nullopt where it has none (no error block, no soft_rmse, a ratio
  // without `sm` or with sm's time 0). `sm` is the baseline of ratios, may be null.
  std::optional<double> (*value)(const Record& record, const Record* sm);
  // Stores a value read from the JSON path (stored figures only).
  void (*store)(Record& record, double value);
  MetricReference reference = MetricReference::None;
  // What the figure says, for tables that explain their metrics (error metrics only).
  std::string_view description = {};
  // A derived figure's inputs: the names of the metrics it is computed from, separated by
  // spaces (empty for a stored figure), so that readers can tell a re-derivation.
  std::string_view from = {};

  bool shownIn(MetricUse use) const { return (uses & use) != 0; }
  // The unit alone, as a sweep table's header names it: "ms", "fps", "MB".
  std::string_view unit() const;
};

// Where a record holds the metric: its stored path, "/work/total/<name>" for a work
// counter, "/derived/<name>" for a carried derived figure, empty for a ratio to the
// baseline `sm` (no record holds it).
std::string recordPath(const Metric& m);
// The names in a derived figure's `from`, in order; none for a stored figure.
std::vector<std::string_view> inputsOf(const Metric& m);
// The names of MetricUse flags, as `testbed metrics --json` lists them.
std::vector<std::string_view> useNames(unsigned uses);

std::span<const Metric> metricTable();
// Throws std::logic_error for a name the table does not hold (a programming error).
const Metric& metric(std::string_view name);
// The metric called `name` among those with `use`, or null.
const Metric* findMetric(std::string_view name, MetricUse use);

// The value with `digits` decimals, "–" where there is none or it is not finite.
std::string formatFixed(std::optional<double> value, int digits);
// "12.3 ms, 1.52x sm, mismatch 0.123%, ..." : the kBrief metrics, 3 significant digits.
std::string briefSummary(const Record& record, const Record* sm, std::string_view separator);

}  // namespace testbed
