#include "testbed/report/regression_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "testbed/core/error.h"
#include "testbed/core/markdown_text.h"
#include "testbed/io/json_input.h"
#include "testbed/io/json_reader.h"
#include "testbed/technique/path.h"

namespace testbed {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw InputError(where + ": " + what); }

// Same scene and setup, any technique: `sm`'s record is the speed reference.
std::string setupKey(const Record& r) {
  std::ostringstream key;
  key << r.scene << ' ' << r.width << 'x' << r.height << ' ' << r.shadowMap << ' ' << r.depthFormat;
  return key.str();
}

std::string formatValue(const Metric& metric, double value) {
  if (metric.integer) return std::to_string(std::uint64_t(value));
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

std::string label(const CheckRecord& c) {
  const Record& r = c.record;
  std::ostringstream out;
  out << markdownText(r.scene) << " · " << markdownText(r.technique) << " · " << r.shadowMap << "² (" << r.width << "×" << r.height << ", depth "
      << markdownText(r.depthFormat) << ")";
  return out.str();
}

const Metric& speedMetric() {
  for (const Metric& m : metricTable())
    if (m.check == CheckRule::Speed) return m;
  throw std::logic_error("the metric table has no speed metric");
}

std::string findingLine(const Finding& f) {
  std::ostringstream line;
  line << "- " << label(*f.record) << ": ";
  if (f.kind == FindingKind::New) return line.str() + "new, not in the baseline\n";
  if (!f.metric) return line.str() + "missing from the current run\n";
  if (!f.pass.empty()) line << "pass " << markdownCode(f.pass) << " ";
  line << f.metric->name;
  if (f.metric->check == CheckRule::Speed) line << " (" << timingName(f.record->record.timing) << " time × sm)";
  line << " " << formatValue(*f.metric, f.baseline) << " → " << formatValue(*f.metric, f.current);
  if (f.metric->check == CheckRule::Exact) {
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
    if (frameTimeMs(r->record) == 0) return "its frame time is 0 in " + markdownText(r->file) + " (not a measurement).";
    if (r->smTimeZero) return "`sm`'s frame time is 0 in " + markdownText(r->file) + " (not a measurement).";
  }
  for (const CheckRecord* r : {&b, &c})
    if (!r->smRatio) return "no `sm` record in the same run (" + markdownText(r->file) + ").";
  return "";
}

void addNote(CheckReport& report, const std::string& note) {
  if (std::find(report.notes.begin(), report.notes.end(), note) == report.notes.end()) report.notes.push_back(note);
}

// Why two matched records' work counts are not compared, as a note; empty when they are.
std::string whyNoWork(const CheckRecord& b, const CheckRecord& c) {
  if (b.record.backend != c.record.backend)
    return "work not compared: the backends differ (baseline " + markdownCode(b.record.backend) + ", current " +
           markdownCode(c.record.backend) + "); another rasterizer counts other work.";
  // One note per reason, not per record: a baseline from before the counters lacks them all.
  for (const CheckRecord* r : {&b, &c})
    if (!r->record.work)
      return r->record.workRecorded
                 ? "work not compared for records whose GL offered no pipeline statistics (`\"work\": null`)."
                 : "work not compared for records made before the work counters (no `work` key): refresh the "
                   "baseline with scripts/baselines.sh.";
  return "";
}

// Each pass's count of each work counter: a pass new in `current` counts from 0, one gone
// from it counts 0, so renaming a pass regresses until the baseline is refreshed.
void compareWork(CheckReport& report, const CheckRecord& b, const CheckRecord& c, double tolerance) {
  std::map<std::string, std::pair<WorkCounts, WorkCounts>> passes;  // name → (baseline, current)
  for (const auto& [name, counts] : b.record.work->passes) passes[name].first = counts;
  for (const auto& [name, counts] : c.record.work->passes) passes[name].second = counts;
  for (const auto& [name, counts] : passes)
    for (std::size_t i = 0; i < kWorkCounters.size(); ++i) {
      const double before = double(counts.first[i]), now = double(counts.second[i]);
      const Metric& m = metric(kWorkCounters[i].name);
      if (now > before * (1 + tolerance))
        report.findings.push_back({FindingKind::Regression, &c, &m, before, now, name});
      else if (now * (1 + tolerance) < before)
        report.findings.push_back({FindingKind::Improvement, &c, &m, before, now, name});
    }
}

std::string plural(int n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

}  // namespace

std::string CheckRecord::key() const { return setupKey(record) + ' ' + record.technique; }

std::vector<CheckRecord> parseCheckRecords(const json& records, const std::string& file) {
  if (!records.is_array()) fail(file, "expected a JSON array of records (a `testbed compare` metrics.json)");
  std::vector<CheckRecord> parsed;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string where = file + ": [" + std::to_string(i) + "]";
    const JsonField r(records[i], "", where);
    if (!r.json().is_object()) r.fail("expected an object (a record)");
    const std::string technique = r["technique"].text();
    if (technique == "groundtruth" || technique == "area") continue;  // references, no error of their own
    CheckRecord record{file, readRecord(r.json(), where), std::nullopt, false};
    if (!record.record.error) fail(where + ".error", "expected an object (records from `testbed compare`)");
    parsed.push_back(std::move(record));
  }
  // Speed is only meaningful as a ratio to `sm` measured in the same run (software rasterizers).
  std::map<std::string, const Record*> sm;
  for (const auto& r : parsed)
    if (r.record.technique == "sm") sm[setupKey(r.record)] = &r.record;
  for (auto& r : parsed) {
    const auto it = sm.find(setupKey(r.record));
    if (it == sm.end()) continue;
    r.smRatio = speedMetric().value(r.record, it->second);
    r.smTimeZero = !(frameTimeMs(*it->second) > 0);
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

int CheckReport::count(FindingKind kind) const {
  return int(std::count_if(findings.begin(), findings.end(), [&](const Finding& f) { return f.kind == kind; }));
}

CheckReport compareRecords(const std::vector<CheckRecord>& baseline, const std::vector<CheckRecord>& current,
                           const CheckTolerances& tolerances) {
  CheckReport report;
  std::map<std::string, const CheckRecord*> byKey;
  for (const auto& c : current) byKey.emplace(c.key(), &c);
  std::map<std::string, bool> matched;
  // A change beyond `slack` in the metric's worse direction regresses, in its better one improves.
  auto judge = [&](const CheckRecord& c, const Metric& metric, double b, double now, double slack) {
    const double gain = metric.better == Better::Lower ? b - now : now - b;
    if (gain < -slack) report.findings.push_back({FindingKind::Regression, &c, &metric, b, now, {}});
    else if (gain > slack) report.findings.push_back({FindingKind::Improvement, &c, &metric, b, now, {}});
  };

  for (const auto& b : baseline) {
    const auto it = byKey.find(b.key());
    if (it == byKey.end()) {
      report.findings.push_back({FindingKind::Regression, &b, nullptr, 0, 0, {}});
      continue;
    }
    const CheckRecord& c = *it->second;
    // The paths run different passes with different memory (docs/paths.md): every pass of
    // one would read as new or gone, so runs of two paths are refused, as merge refuses them.
    if (b.record.path && c.record.path && *b.record.path != *c.record.path)
      throw InputError(c.file + ": " + label(c) + ": made on the " + std::string(pathName(*c.record.path)) +
                       " path, the baseline's (" + b.file + ") on the " + std::string(pathName(*b.record.path)) +
                       " path; check compares runs of one path (--path)");
    if (b.record.path.has_value() != c.record.path.has_value())
      addNote(report, "records made before the path was recorded (no `path` key) are compared as if on the other "
                      "side's path; refresh the baseline with scripts/baselines.sh.");
    matched[c.key()] = true;
    ++report.compared;

    for (const Metric& m : metricTable()) {
      if (m.check != CheckRule::Error) continue;
      const std::optional<double> before = m.value(b.record, nullptr), now = m.value(c.record, nullptr);
      if (!before || !now) continue;  // soft_rmse only where both records have one
      judge(c, m, *before, *now, std::max(tolerances.error * std::abs(*before), m.floor));
    }

    const Record &br = b.record, &cr = c.record;
    if (compiledBy(br) != compiledBy(cr))
      addNote(report, "shaders compiled by different front-ends (baseline " + std::string(shaderPathName(compiledBy(br))) +
                          ", current " + std::string(shaderPathName(compiledBy(cr))) +
                          "): they may round filtered visibility differently (docs/portability.md), so a small "
                          "accuracy change can be the compiler's.");
    if (br.technique != "sm") {  // sm is the speed reference: its ratio is 1 by definition
      if (br.backend != cr.backend) {
        addNote(report, "speed not compared: the backends differ (baseline " + markdownCode(br.backend) + ", current " +
                            markdownCode(cr.backend) +
                            "); frame times from different devices are not comparable. Accuracy and memory were "
                            "still checked.");
      } else if (br.timing != cr.timing) {
        addNote(report, "speed not compared where the timing source differs (baseline " +
                            std::string(timingName(br.timing)) + ", current " + std::string(timingName(cr.timing)) +
                            ").");
      } else if (const std::string why = whyNoRatio(b, c); !why.empty()) {
        addNote(report, "speed not compared for " + label(b) + ": " + why);
      } else {
        // A ratio above baseline × (1 + tol) is slower; below baseline / (1 + tol) faster (symmetric).
        const double bRatio = *b.smRatio, cRatio = *c.smRatio;
        if (cRatio > bRatio * (1 + tolerances.speed))
          report.findings.push_back({FindingKind::Regression, &c, &speedMetric(), bRatio, cRatio, {}});
        else if (cRatio * (1 + tolerances.speed) < bRatio)
          report.findings.push_back({FindingKind::Improvement, &c, &speedMetric(), bRatio, cRatio, {}});
      }
    }

    if (const std::string why = whyNoWork(b, c); !why.empty())
      addNote(report, why);
    else
      compareWork(report, b, c, tolerances.work);

    // Memory is counted exactly by the GL wrappers, so any increase is real.
    for (const Metric& m : metricTable())
      if (m.check == CheckRule::Exact)
        if (const auto before = m.value(br, nullptr), now = m.value(cr, nullptr); before && now)
          judge(c, m, *before, *now, 0.0);
  }
  for (const auto& c : current)
    if (!matched.count(c.key())) report.findings.push_back({FindingKind::New, &c, nullptr, 0, 0, {}});
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
  char tolerance[128];
  std::snprintf(tolerance, sizeof tolerance, "speed tolerance %g%%, error tolerance %g%%, work tolerance %g%%",
                tolerances.speed * 100, tolerances.error * 100, tolerances.work * 100);
  md << "\n**" << (report.failed() ? "FAIL" : "PASS") << "**: "
     << plural(report.count(FindingKind::Regression), "regression") << ", "
     << plural(report.count(FindingKind::Improvement), "improvement") << ", "
     << plural(report.count(FindingKind::New), "new record") << "; " << report.compared << " of "
     << report.compared + std::count_if(report.findings.begin(), report.findings.end(),
                                        [](const Finding& f) { return f.kind == FindingKind::Regression && !f.metric; })
     << " baseline records matched (" << tolerance << ").\n";
  return md.str();
}

}  // namespace testbed
