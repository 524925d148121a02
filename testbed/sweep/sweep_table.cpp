#include "testbed/sweep/sweep_table.h"

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <set>
#include <sstream>

#include "testbed/core/error.h"
#include "testbed/core/markdown_text.h"

namespace testbed {
namespace {

using nlohmann::json;

// The G-buffer's and the technique's shares of `pass` in `record`, in the record's timing.
struct PassShare {
  double gbufferMs = 0, techniqueMs = 0;
};

PassShare passShare(const Record& record, const std::string& pass, const SweepSpec& spec, std::size_t row) {
  if (pass == "gbuffer") return {record.gbufferMs, 0};
  if (pass == "frame") return {record.gbufferMs, record.timed().totalMs};
  if (pass == "shading" && record.shadingMs) return {0, *record.shadingMs};
  const auto& passes = record.timed().passesMs;
  const auto it = passes.find(pass);
  if (it == passes.end()) {
    std::string known = record.shadingMs ? "gbuffer, frame, shading" : "gbuffer, frame";
    for (const auto& [name, value] : passes) known += ", " + name;
    throw InputError(spec.file.string() + ": rows[" + std::to_string(row) + "].passes: " + record.technique +
                     " has no pass '" + pass + "' (its passes: " + known + ")");
  }
  return {0, it->second};
}

// One technique's value in the table's measure; a row with `passes` measures the frame
// made of those passes alone.
double cellValue(const Record& record, const SweepSpec& spec, std::size_t row) {
  const SweepRow& r = spec.rows[row];
  if (!r.passes) return spec.measure.value(record).value_or(NAN);
  Record part = record;
  part.gbufferMs = 0;
  PassesRecord& timed = part.timing == TimingSource::Wall ? part.wall : part.gpu;
  timed.totalMs = 0;
  for (const auto& pass : *r.passes) {
    const PassShare share = passShare(record, pass, spec, row);
    part.gbufferMs += share.gbufferMs;
    timed.totalMs += share.techniqueMs;
  }
  return spec.measure.value(part).value_or(NAN);
}

}  // namespace

void checkSweepPasses(const SweepSpec& spec, const SweepPlan& plan, std::size_t cell, const Record& record) {
  for (std::size_t row = 0; row < spec.rows.size(); ++row) {
    if (!spec.rows[row].passes) continue;
    bool reads = false;
    for (const auto& entry : plan.entries[row]) reads = reads || std::find(entry.begin(), entry.end(), cell) != entry.end();
    if (!reads) continue;
    for (const auto& pass : *spec.rows[row].passes) passShare(record, pass, spec, row);
  }
}

namespace {

// Cost of `value` relative to `baseline` (> 1: dearer than sm), whatever the measure.
std::optional<double> costRatio(std::optional<double> value, std::optional<double> baseline, const SweepMeasure& measure) {
  if (!value || !baseline || *value <= 0 || *baseline <= 0) return std::nullopt;
  return measure.better() == Better::Higher ? *baseline / *value : *value / *baseline;
}

std::optional<double> difference(std::optional<double> value, std::optional<double> baseline) {
  if (!value || !baseline) return std::nullopt;
  return *value - *baseline;
}

bool isSmRow(const SweepRow& row) { return row.techniques == std::vector<std::string>{"sm"} && !row.passes; }

std::string number(std::optional<double> value, int decimals) {
  if (!value || !std::isfinite(*value)) return "—";
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", std::abs(*value) >= 100 ? std::min(decimals, 1) : decimals, *value);
  return text;
}

json optionals(const std::vector<std::optional<double>>& values) {
  json list = json::array();
  for (const auto& v : values) list.push_back(v && std::isfinite(*v) ? json(*v) : json(nullptr));
  return list;
}

}  // namespace

SweepTable buildSweepTable(const SweepSpec& spec, const SweepPlan& plan, const std::map<std::size_t, Record>& records) {
  SweepTable table;
  table.name = spec.name;
  table.title = spec.title;
  table.citation = spec.citation;
  table.note = spec.note;
  table.unit = spec.measure.unit();
  table.measure = spec.measure.name;
  table.errorMeasure = spec.measure.error();
  table.digits = spec.measure.digits();
  for (const auto& column : spec.columns) table.columns.push_back(column.label);
  table.paperColumns.assign(spec.columns.size(), false);
  for (const auto& row : spec.rows)
    for (std::size_t c = 0; c < row.paper.size(); ++c) table.paperColumns[c] = table.paperColumns[c] || row.paper[c].has_value();
  for (const auto& [cell, record] : records) {
    const std::string& backend = record.backend;
    if (!table.backend.empty() && table.backend != backend)
      throw std::logic_error("buildSweepTable: records of several backends (" + table.backend + ", " + backend + ")");
    table.backend = backend;
  }
  for (std::size_t r = 0; r < spec.rows.size(); ++r) {
    SweepTableRow row{spec.rows[r].group, spec.rows[r].label, spec.rows[r].notMeasured, {}, spec.rows[r].paper, {}, {}, {}, {}};
    for (std::size_t c = 0; c < spec.columns.size(); ++c) {
      std::optional<double> value;
      if (!plan.entries[r][c].empty()) {
        double sum = 0;
        bool complete = true;
        for (const std::size_t cell : plan.entries[r][c]) {
          const auto it = records.find(cell);
          if (it == records.end()) complete = false;
          else sum += cellValue(it->second, spec, r);
        }
        if (complete) value = sum / double(plan.entries[r][c].size());
      }
      row.ours.push_back(value);
    }
    table.rows.push_back(std::move(row));
  }
  // The baseline of a row: the `sm` row of its group, else the table's first `sm` row.
  // Ours divides only by a baseline of the same frame set-up.
  for (std::size_t r = 0; r < spec.rows.size(); ++r) {
    std::optional<std::size_t> baseline;
    for (std::size_t b = 0; b < spec.rows.size(); ++b)
      if (isSmRow(spec.rows[b]) && (!baseline || (spec.rows[b].group == spec.rows[r].group &&
                                                  spec.rows[*baseline].group != spec.rows[r].group)))
        baseline = b;
    if (baseline) table.hasRatios = true;
    auto& row = table.rows[r];
    for (std::size_t c = 0; c < spec.columns.size(); ++c) {
      if (!baseline) {
        row.oursRatio.push_back(std::nullopt);
        row.paperRatio.push_back(std::nullopt);
        row.oursDifference.push_back(std::nullopt);
        row.paperDifference.push_back(std::nullopt);
        continue;
      }
      const auto& ours = plan.entries[r][c];
      const auto& base = plan.entries[*baseline][c];
      const bool sameFrame = !ours.empty() && !base.empty() &&
                             plan.cells[ours.front()].frameKey() == plan.cells[base.front()].frameKey();
      row.oursRatio.push_back(sameFrame ? costRatio(row.ours[c], table.rows[*baseline].ours[c], spec.measure) : std::nullopt);
      row.paperRatio.push_back(costRatio(row.paper[c], table.rows[*baseline].paper[c], spec.measure));
      row.oursDifference.push_back(sameFrame ? difference(row.ours[c], table.rows[*baseline].ours[c]) : std::nullopt);
      row.paperDifference.push_back(difference(row.paper[c], table.rows[*baseline].paper[c]));
    }
  }
  table.hasDifferences = spec.differences && table.hasRatios;
  return table;
}

namespace {

bool anyPaperColumn(const SweepTable& table) {
  return std::find(table.paperColumns.begin(), table.paperColumns.end(), true) != table.paperColumns.end();
}

// One numeric column of the Markdown table: its heading and where its figures are.
struct FigureColumn {
  std::string heading;
  std::vector<std::optional<double>> SweepTableRow::*values;
  std::size_t column;  // the spec's column the figures belong to
  int digits;
};

// The Markdown table's numeric columns: every spec column's figures, ours and the paper's;
// then per spec column its comparisons with sm, in the order the HTML page writes each
// entry (report/report_html.cpp sweepEntryText: ours, the paper's, ×SM, −SM), so a
// column's −SM stands beside its ×SM.
std::vector<FigureColumn> figureColumns(const SweepTable& table) {
  const bool anyPaper = anyPaperColumn(table);
  std::vector<FigureColumn> out;
  auto add = [&](std::size_t c, const char* mark, auto ours, auto paper, int digits) {
    const std::string name = markdownText(table.columns[c]);
    out.push_back({name + (anyPaper ? " ours" : "") + mark, ours, c, digits});
    if (c < table.paperColumns.size() && table.paperColumns[c]) out.push_back({name + " paper" + mark, paper, c, digits});
  };
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    add(c, "", &SweepTableRow::ours, &SweepTableRow::paper, table.digits);
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    if (table.hasRatios) add(c, " ×SM", &SweepTableRow::oursRatio, &SweepTableRow::paperRatio, 2);
    if (table.hasDifferences)
      add(c, " −SM", &SweepTableRow::oursDifference, &SweepTableRow::paperDifference, table.digits);
  }
  return out;
}

}  // namespace

std::string sweepTableMarkdown(const SweepTable& table, const SweepHeader& header) {
  std::ostringstream md;
  const bool anyPaper = anyPaperColumn(table);
  md << "# " << markdownText(table.title.empty() ? table.name : table.title) << "\n\n";
  if (!table.citation.empty()) md << "Paper: " << markdownText(table.citation) << ". ";
  else if (!anyPaper) md << "A study of one's own (no paper's figures). ";
  md << "Measure: `" << table.measure << "`" << (table.unit.empty() ? "" : " (" + table.unit + ")");
  if (table.unit == "ms" || table.unit == "fps")
    md << " of the whole frame (G-buffer and every pass of the technique, shadow map included)";
  md << ".";
  if (table.hasRatios)
    md << (table.errorMeasure ? " `×SM`: error relative to shadow mapping in the same column"
                              : " `×SM`: cost relative to shadow mapping in the same column (time, or memory)")
       << (anyPaper ? ", ours against ours and the paper's against the paper's." : ".");
  if (table.hasDifferences) md << " `−SM`: the difference to shadow mapping in the same column, in " << table.unit << ".";
  md << "\n\n";
  for (const auto& [name, value] : header) md << "- " << name << ": " << markdownText(value) << "\n";
  if (!header.empty()) md << "\n";
  if (!table.note.empty()) md << table.note << "\n\n";

  const bool groups = std::any_of(table.rows.begin(), table.rows.end(), [](const auto& r) { return !r.group.empty(); });
  const std::vector<FigureColumn> figures = figureColumns(table);
  md << "|" << (groups ? " |" : "") << " technique |";
  for (const FigureColumn& f : figures) md << " " << f.heading << " |";
  md << "\n|" << (groups ? "---|" : "") << "---|";
  for (std::size_t i = 0; i < figures.size(); ++i) md << "---:|";
  md << "\n";
  std::string lastGroup;
  for (std::size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    md << "|";
    if (groups) md << " " << (r == 0 || row.group != lastGroup ? markdownText(row.group) : "") << " |";
    lastGroup = row.group;
    md << " " << markdownText(row.label) << (row.notMeasured.empty() ? "" : " †") << " |";
    for (const FigureColumn& f : figures) md << " " << number((row.*f.values)[f.column], f.digits) << " |";
    md << "\n";
  }
  std::set<std::string> footnotes;  // each row label and reason once, however many groups repeat it
  for (const auto& row : table.rows)
    if (!row.notMeasured.empty() && footnotes.insert(row.label + ": " + row.notMeasured).second)
      md << (footnotes.size() == 1 ? "\n" : "") << "† " << markdownText(row.label) << ": " << markdownText(row.notMeasured)
         << "\n";
  return md.str();
}

json sweepTableJson(const SweepTable& table, const SweepHeader& header) {
  json rows = json::array();
  for (const auto& row : table.rows)
    rows.push_back({{"group", row.group}, {"label", row.label}, {"not_measured", row.notMeasured},
                    {"ours", optionals(row.ours)}, {"paper", optionals(row.paper)},
                    {"ours_ratio", optionals(row.oursRatio)}, {"paper_ratio", optionals(row.paperRatio)}});
  if (table.hasDifferences)
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      rows[r]["ours_difference"] = optionals(table.rows[r].oursDifference);
      rows[r]["paper_difference"] = optionals(table.rows[r].paperDifference);
    }
  json head = json::object();
  for (const auto& [name, value] : header) head[name] = value;
  const bool anyPaper = std::find(table.paperColumns.begin(), table.paperColumns.end(), true) != table.paperColumns.end();
  return {{"name", table.name},       {"title", table.title}, {"citation", table.citation},
          {"unit", table.unit},       {"measure", table.measure}, {"backend", table.backend},
          {"columns", table.columns}, {"paper_columns", table.paperColumns}, {"has_paper", anyPaper},
          {"has_ratios", table.hasRatios}, {"has_differences", table.hasDifferences}, {"rows", rows}, {"header", head}};
}

}  // namespace testbed
