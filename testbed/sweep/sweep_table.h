#pragma once
// A paper's table rebuilt from sweep records: the paper's rows and columns, our figure
// beside the paper's, and each one's ratio to plain shadow mapping in the same column
// (on a software rasterizer only the ratios compare with a paper's GPU).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/harness/record.h"
#include "testbed/sweep/sweep_plan.h"
#include "testbed/sweep/sweep_spec.h"

namespace testbed {

struct SweepTableRow {
  std::string group, label, notMeasured;
  std::vector<std::optional<double>> ours, paper, oursRatio, paperRatio;
  std::vector<std::optional<double>> oursDifference, paperDifference;  // minus sm's; with SweepTable::hasDifferences
};

struct SweepTable {
  std::string name, title, citation, note, unit, backend;
  std::string measure;       // the metric table's name of what the table's numbers are
  bool errorMeasure = false;  // an error metric (its ratio to sm is an error ratio, not a cost)
  std::vector<std::string> columns;
  // Per column: whether any row has the paper's figure there. Columns without are left
  // out (a study of one's own has none at all).
  std::vector<bool> paperColumns;
  std::vector<SweepTableRow> rows;
  int digits = 2;          // decimals of the measure (the metric table's)
  bool hasRatios = false;  // false when the table has no `sm` row to divide by
  bool hasDifferences = false;  // the spec's "differences", where there are ratios
};

// Lines above the table naming how it was made (command, machine, backend, build).
using SweepHeader = std::vector<std::pair<std::string, std::string>>;

// `records`: cell index → record, all of one backend. Cells without a record read as
// missing ("—"). Throws InputError naming the spec's row when a row's pass is unknown.
SweepTable buildSweepTable(const SweepSpec& spec, const SweepPlan& plan,
                           const std::map<std::size_t, Record>& records);

// The same check for one record as soon as it is made, so that a spec naming a pass its
// technique does not have stops at that cell's first render, not after the whole sweep:
// throws InputError naming the row when a row whose entries read `cell` names a pass
// `record` lacks. A technique reports its passes only by rendering.
void checkSweepPasses(const SweepSpec& spec, const SweepPlan& plan, std::size_t cell, const Record& record);

std::string sweepTableMarkdown(const SweepTable& table, const SweepHeader& header);
// The same data for scripts/sweep_plot.py.
nlohmann::json sweepTableJson(const SweepTable& table, const SweepHeader& header);

}  // namespace testbed
