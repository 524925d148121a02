#include "testbed/report/regression_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"

namespace testbed {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

const json& field(const json& object, const char* name, const std::string& where) {
  if (!object.is_object()) fail(where, "expected an object");
  const auto it = object.find(name);
  if (it == object.end()) fail(where + "." + name, "missing");
  return *it;
}

std::string text(const json& object, const char* name, const std::string& where) {
  const json& value = field(object, name, where);
  if (!value.is_string()) fail(where + "." + name, "expected a string");
  return value.get<std::string>();
}

double number(const json& object, const char* name, const std::string& where) {
  const json& value = field(object, name, where);
  if (!value.is_number()) fail(where + "." + name, "expected a number");
  return value.get<double>();
}

// Times, error metrics and distances are measured magnitudes: a negative one is a
// corrupt record, not a huge improvement.
double nonNegative(const json& object, const char* name, const std::string& where) {
  const double value = number(object, name, where);
  if (value < 0) fail(where + "." + name, "expected a non-negative number, got " + std::to_string(value));
  return value;
}

std::int64_t count(const json& object, const char* name, const std::string& where) {
  const json& value = field(object, name, where);
  if (!value.is_number_integer() || value.get<std::int64_t>() < 0)
    fail(where + "." + name, "expected a non-negative integer");
  return value.get<std::int64_t>();
}

// The metrics compared, in report order; soft_rmse only where both records have one.
const char* const kPlainMetrics[] = {"mismatch_pct", "edge_mismatch_pct", "leak_pct", "overestimation_pct", "rmse"};

CheckRecord parseRecord(const json& r, const std::string& file, const std::string& where) {
  CheckRecord record;
  record.file = file;
  record.technique = text(r, "technique", where);
  record.scene = text(r, "scene", where);
  const json& size = field(r, "size", where);
  if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer())
    fail(where + ".size", "expected [width, height]");
  record.width = size[0].get<int>();
  record.height = size[1].get<int>();
  record.shadowMap = int(count(r, "shadow_map", where));
  record.depthFormat = text(r, "depth_format", where);
  record.backend = text(r, "backend", where);
  record.timing = text(r, "timing", where);
  if (record.timing != "gpu" && record.timing != "wall") fail(where + ".timing", "expected \"gpu\" or \"wall\"");
  const char* times = record.timing == "wall" ? "wall_ms" : "gpu_ms";
  record.frameMs = nonNegative(field(r, times, where), "total", where + "." + times);
  record.memoryBytes = std::uint64_t(count(r, "memory_bytes", where));

  const json& error = field(r, "error", where);
  const std::string errorWhere = where + ".error";
  if (!error.is_object()) fail(errorWhere, "expected an object (records from `testbed compare`)");
  for (const char* name : kPlainMetrics) record.errors.emplace_back(name, nonNegative(error, name, errorWhere));
  record.errors.emplace_back("boundary_px.mean", nonNegative(field(error, "boundary_px", errorWhere), "mean",
                                                             errorWhere + ".boundary_px"));
  std::optional<double> soft;
  if (error.contains("soft_rmse") && !error["soft_rmse"].is_null())
    soft = nonNegative(error, "soft_rmse", errorWhere);
  record.errors.emplace_back("soft_rmse", soft);
  return record;
}

// Same scene and setup, any technique: `sm`'s record is the speed reference.
std::string setupKey(const CheckRecord& r) {
  std::ostringstream key;
  key << r.scene << ' ' << r.width << 'x' << r.height << ' ' << r.shadowMap << ' ' << r.depthFormat;
  return key.str();
}

std::string formatValue(const std::string& metric, double value) {
  if (metric == "memory_bytes") return std::to_string(std::uint64_t(value));
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

std::string label(const CheckRecord& r) {
  std::ostringstream out;
  out << r.scene << " · " << r.technique << " · " << r.shadowMap << "² (" << r.width << "×" << r.height << ", depth "
      << r.depthFormat << ")";
  return out.str();
}

std::string findingLine(const Finding& f) {
  std::ostringstream line;
  line << "- " << label(*f.record) << ": ";
  if (f.kind == FindingKind::New) return line.str() + "new, not in the baseline\n";
  if (f.metric == "missing") return line.str() + "missing from the current run\n";
  line << f.metric;
  if (f.metric == "speed_ratio") line << " (" << f.record->timing << " time × sm)";
  line << " " << formatValue(f.metric, f.baseline) << " → " << formatValue(f.metric, f.current);
  if (f.metric == "memory_bytes") {
    const auto delta = std::int64_t(f.current) - std::int64_t(f.baseline);
    line << " (" << (delta > 0 ? "+" : "") << delta << " bytes)";
  } else if (f.baseline != 0) {
    char change[32];
    std::snprintf(change, sizeof change, " (%+.1f%%)", (f.current - f.baseline) / std::abs(f.baseline) * 100.0);
    line << change;
  }
  return line.str() + "\n";
}

// Why two matched records have no speed ratio to compare; empty when both have one.
std::string whyNoRatio(const CheckRecord& b, const CheckRecord& c) {
  for (const CheckRecord* r : {&b, &c}) {
    if (r->frameMs == 0) return "its frame time is 0 in " + r->file + " (not a measurement).";
    if (r->smTimeZero) return "`sm`'s frame time is 0 in " + r->file + " (not a measurement).";
  }
  for (const CheckRecord* r : {&b, &c})
    if (!r->smRatio) return "no `sm` record in the same run (" + r->file + ").";
  return "";
}

void addNote(CheckReport& report, const std::string& note) {
  if (std::find(report.notes.begin(), report.notes.end(), note) == report.notes.end()) report.notes.push_back(note);
}

std::string plural(int n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

}  // namespace

std::string CheckRecord::key() const { return setupKey(*this) + ' ' + technique; }

std::vector<CheckRecord> parseCheckRecords(const json& records, const std::string& file) {
  if (!records.is_array()) fail(file, "expected a JSON array of records (a `testbed compare` metrics.json)");
  std::vector<CheckRecord> parsed;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string where = file + ": [" + std::to_string(i) + "]";
    const std::string technique = text(records[i], "technique", where);
    if (technique == "groundtruth" || technique == "area") continue;  // references, no error of their own
    parsed.push_back(parseRecord(records[i], file, where));
  }
  // Speed is only meaningful as a ratio to `sm` measured in the same run (software rasterizers).
  std::map<std::string, double> smMs;
  for (const auto& r : parsed)
    if (r.technique == "sm") smMs[setupKey(r)] = r.frameMs;
  for (auto& r : parsed) {
    const auto it = smMs.find(setupKey(r));
    if (it == smMs.end()) continue;
    if (it->second > 0) r.smRatio = r.frameMs / it->second;
    else r.smTimeZero = true;
  }
  return parsed;
}

std::vector<CheckRecord> loadCheckRecords(const std::filesystem::path& path, const std::string& option) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(option + ": " + path.string() + ": no such file or folder");
  std::vector<fs::path> files;
  if (!fs::is_directory(path, ec)) {
    files.push_back(path);
  } else if (fs::is_regular_file(path / "metrics.json", ec)) {
    files.push_back(path / "metrics.json");
  } else {
    for (const auto& entry : fs::recursive_directory_iterator(path, ec))
      if (entry.path().filename() == "metrics.json" && entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw InputError(option + ": " + path.string() + ": no metrics.json in it or below it");
  }
  std::vector<CheckRecord> all;
  std::map<std::string, std::string> seen;  // key → file, so one setup is never counted twice
  for (const auto& file : files) {
    const json records = readJsonInput(file);  // regular files only, size-capped, strict
    for (auto& r : parseCheckRecords(records, file.string())) {
      const auto [it, fresh] = seen.emplace(r.key(), r.file);
      if (!fresh) throw InputError(r.file + ": " + label(r) + " appears twice (also in " + it->second + ")");
      all.push_back(std::move(r));
    }
  }
  return all;
}

double errorFloor(const std::string& metric) {
  if (metric == "rmse" || metric == "soft_rmse") return 0.001;
  if (metric == "boundary_px.mean") return 0.01;  // pixels
  return 0.01;                                    // the *_pct metrics: percentage points
}

int CheckReport::count(FindingKind kind) const {
  return int(std::count_if(findings.begin(), findings.end(), [&](const Finding& f) { return f.kind == kind; }));
}

CheckReport compareRecords(const std::vector<CheckRecord>& baseline, const std::vector<CheckRecord>& current,
                           const CheckTolerances& tolerances) {
  CheckReport report;
  std::map<std::string, const CheckRecord*> byKey;
  for (const auto& c : current) byKey.emplace(c.key(), &c);
  std::map<std::string, bool> matched;
  auto judge = [&](const CheckRecord& c, const std::string& metric, double b, double now, double slack) {
    if (now > b + slack) report.findings.push_back({FindingKind::Regression, &c, metric, b, now});
    else if (now < b - slack) report.findings.push_back({FindingKind::Improvement, &c, metric, b, now});
  };

  for (const auto& b : baseline) {
    const auto it = byKey.find(b.key());
    if (it == byKey.end()) {
      report.findings.push_back({FindingKind::Regression, &b, "missing", 0, 0});
      continue;
    }
    const CheckRecord& c = *it->second;
    matched[c.key()] = true;
    ++report.compared;

    for (const auto& [metric, value] : b.errors) {
      const auto other = std::find_if(c.errors.begin(), c.errors.end(), [&](const auto& e) { return e.first == metric; });
      if (!value || other == c.errors.end() || !other->second) continue;
      judge(c, metric, *value, *other->second, std::max(tolerances.error * std::abs(*value), errorFloor(metric)));
    }

    if (b.technique != "sm") {  // sm is the speed reference: its ratio is 1 by definition
      if (b.backend != c.backend) {
        addNote(report, "speed not compared: the backends differ (baseline `" + b.backend + "`, current `" + c.backend +
                            "`); frame times from different devices are not comparable. Accuracy and memory were "
                            "still checked.");
      } else if (b.timing != c.timing) {
        addNote(report, "speed not compared where the timing source differs (baseline " + b.timing + ", current " +
                            c.timing + ").");
      } else if (const std::string why = whyNoRatio(b, c); !why.empty()) {
        addNote(report, "speed not compared for " + label(b) + ": " + why);
      } else {
        // A ratio above baseline × (1 + tol) is slower; below baseline / (1 + tol) faster (symmetric).
        const double bRatio = *b.smRatio, cRatio = *c.smRatio;
        if (cRatio > bRatio * (1 + tolerances.speed))
          report.findings.push_back({FindingKind::Regression, &c, "speed_ratio", bRatio, cRatio});
        else if (cRatio * (1 + tolerances.speed) < bRatio)
          report.findings.push_back({FindingKind::Improvement, &c, "speed_ratio", bRatio, cRatio});
      }
    }

    // Memory is counted exactly by the GL wrappers, so any increase is real.
    judge(c, "memory_bytes", double(b.memoryBytes), double(c.memoryBytes), 0.0);
  }
  for (const auto& c : current)
    if (!matched.count(c.key())) report.findings.push_back({FindingKind::New, &c, "new", 0, 0});
  return report;
}

std::string checkReportMarkdown(const CheckReport& report, const CheckTolerances& tolerances) {
  std::ostringstream md;
  md << "# Regression check\n";
  const std::pair<FindingKind, const char*> sections[] = {
      {FindingKind::Regression, "Regressions"}, {FindingKind::Improvement, "Improvements"}, {FindingKind::New, "New"}};
  for (const auto& [kind, title] : sections) {
    if (report.count(kind) == 0) continue;
    md << "\n## " << title << " (" << report.count(kind) << ")\n\n";
    for (const auto& f : report.findings)
      if (f.kind == kind) md << findingLine(f);
  }
  if (!report.notes.empty()) {
    md << "\n## Notes\n\n";
    for (const auto& note : report.notes) md << "- " << note << "\n";
  }
  char tolerance[96];
  std::snprintf(tolerance, sizeof tolerance, "speed tolerance %g%%, error tolerance %g%%", tolerances.speed * 100,
                tolerances.error * 100);
  md << "\n**" << (report.failed() ? "FAIL" : "PASS") << "**: "
     << plural(report.count(FindingKind::Regression), "regression") << ", "
     << plural(report.count(FindingKind::Improvement), "improvement") << ", "
     << plural(report.count(FindingKind::New), "new record") << "; " << report.compared << " of "
     << report.compared + std::count_if(report.findings.begin(), report.findings.end(),
                                        [](const Finding& f) { return f.metric == "missing"; })
     << " baseline records matched (" << tolerance << ").\n";
  return md.str();
}

}  // namespace testbed
