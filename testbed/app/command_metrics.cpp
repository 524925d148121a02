// `testbed metrics [--json] [--derive FILE]`: the metric table (harness/metric_table.h) for
// the scripts and people that read records, and the derived figures of records written
// before records carried them.
#include <iomanip>
#include <iostream>

#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/app/commands.h"
#include "testbed/core/error.h"
#include "testbed/harness/metric_table.h"
#include "testbed/harness/record.h"
#include "testbed/io/json_input.h"

namespace testbed {
namespace {

using nlohmann::json;

std::string_view checkName(CheckRule rule) {
  switch (rule) {
    case CheckRule::Error: return "error";
    case CheckRule::Speed: return "speed";
    case CheckRule::Exact: return "exact";
    case CheckRule::Work: return "work";
    case CheckRule::None: break;
  }
  return "none";
}

// The summaries over frames that a sequence record's "series" holds for every stored
// metric (harness/sequence.cpp), which a sweep spec's measure names as "<id>.<summary>".
constexpr std::string_view kSeriesSummaries[] = {"mean", "p95", "max"};

json metricJson(const Metric& m) {
  const std::string path = recordPath(m);
  json summaries = json::array();
  if (!m.path.empty())
    for (std::string_view s : kSeriesSummaries) summaries.push_back(s);
  return {{"id", m.name},
          {"heading", m.heading},
          {"brief", m.brief},
          {"description", m.description},
          {"unit", m.unit()},
          {"suffix", m.suffix},
          {"digits", m.digits},
          {"better", m.better == Better::Lower ? "lower" : "higher"},
          {"reference", m.reference == MetricReference::None ? "none" : referenceName(m.reference)},
          {"path", path.empty() ? json(nullptr) : json(path)},
          {"derived", !m.from.empty()},
          {"from", inputsOf(m)},
          // A ratio to the baseline technique's record, which no single record holds.
          {"relative_to", path.empty() ? json("sm") : json(nullptr)},
          {"integer", m.integer},
          {"nullable", m.nullable},
          {"check", checkName(m.check)},
          {"floor", m.floor},
          {"shown_in", useNames(m.uses)},
          {"summaries_over_frames", summaries},
          {"series_path", m.path.empty() ? json(nullptr) : json("/sequence/series/" + std::string(m.name))}};
}

// The baseline of a record's ratios: the file's first `sm` record of the same scene,
// image size, map size and depth format.
const Record* baselineOf(const Record& r, const std::vector<Record>& all) {
  for (const Record& b : all)
    if (b.technique == "sm" && b.scene == r.scene && b.width == r.width && b.height == r.height &&
        b.shadowMap == r.shadowMap && b.depthFormat == r.depthFormat)
      return &b;
  return nullptr;
}

// Each record's "derived" block as the record writer computes it, with the ratios to the
// baseline where the file holds one.
json derivedOf(const std::string& file) {
  const json records = readJsonInput(file);
  if (!records.is_array()) throw InputError(file + ": expected an array of records");
  std::vector<Record> all;
  for (std::size_t i = 0; i < records.size(); ++i)
    all.push_back(readRecord(records[i], file + ": [" + std::to_string(i) + "]"));
  json out = json::array();
  for (const Record& r : all) {
    const json written = r;
    json derived = written.value("derived", json::object());
    if (const Record* sm = baselineOf(r, all))
      for (const Metric& m : metricTable())
        if (recordPath(m).empty())
          if (const auto v = m.value(r, sm)) derived[std::string(m.name)] = *v;
    out.push_back(derived);
  }
  return out;
}

}  // namespace

CommandRunner addMetricsCommand(CLI::App& app) {
  auto* command = app.add_subcommand("metrics", "list the metric table: what a record measures and derives");
  auto asJson = std::make_shared<bool>(false);
  auto derive = std::make_shared<std::string>();
  command->add_flag("--json", *asJson, "print the table as JSON");
  command->add_option("--derive", *derive,
                      "print the derived figures of every record in FILE (metrics.json, records.json) as JSON, "
                      "with the ratios to the file's sm record of the same scene and sizes");
  return {command, [asJson, derive]() {
    if (!derive->empty()) {
      std::cout << derivedOf(*derive).dump() << "\n";
      return 0;
    }
    if (*asJson) {
      json all = json::array();
      for (const Metric& m : metricTable()) all.push_back(metricJson(m));
      std::cout << all.dump(1) << "\n";
      return 0;
    }
    for (const Metric& m : metricTable()) {
      const std::string path = recordPath(m);
      std::cout << std::left << std::setw(28) << m.name << std::setw(15) << m.unit() << std::setw(8)
                << (m.better == Better::Lower ? "lower" : "higher") << std::setw(6)
                << (m.reference == MetricReference::None ? "-" : referenceName(m.reference)) << " "
                << (path.empty() ? "ratio to sm" : path) << "\n";
    }
    return 0;
  }};
}

}  // namespace testbed
