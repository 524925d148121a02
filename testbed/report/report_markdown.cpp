#include <algorithm>
#include <sstream>
#include <utility>
#include <vector>

#include "testbed/core/markdown_text.h"
#include "testbed/harness/metric_table.h"
#include "testbed/report/comparison.h"

namespace testbed {
namespace {

std::string fixedMetric(const char* name, const Record& record, const Record* sm) {
  const Metric& m = metric(name);
  return formatFixed(m.value(record, sm), m.digits);
}

// One row of "Where the time goes": the technique's passes, longest first, each with its
// share of the technique's time, so a reader sees which pass a speed ratio comes from.
void passRow(std::ostringstream& md, const Record& r) {
  std::vector<std::pair<std::string, double>> passes(r.timed().passesMs.begin(), r.timed().passesMs.end());
  std::stable_sort(passes.begin(), passes.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  const double total = r.timed().totalMs;
  md << "| " << markdownCode(r.technique) << " | " << formatFixed(total, 2) << " |";
  const char* separator = " ";
  for (const auto& [name, ms] : passes) {
    md << separator << markdownText(name) << " " << formatFixed(ms, 2);
    if (total > 0) md << " (" << formatFixed(100.0 * ms / total, 0) << " %)";
    separator = " · ";
  }
  md << " |\n";
}

// Rows of "Work per pass": the technique's pipeline statistics pass by pass, by pass name.
void workRows(std::ostringstream& md, const Record& r) {
  if (!r.work) return;
  for (const auto& [name, counts] : r.work->passes) {
    md << "| " << markdownCode(r.technique) << " | " << markdownText(name) << " |";
    for (const std::uint64_t count : counts) md << " " << count << " |";
    md << "\n";
  }
}

void workSection(std::ostringstream& md, const Comparison& c) {
  md << "\n## Work per pass\n\n";
  if (!baselineRecord(c).work) {
    md << "Not counted: the GL (" << markdownText(baselineRecord(c).backend)
       << ") offers no pipeline statistics (ARB_pipeline_statistics_query).\n";
    return;
  }
  md << "Pipeline statistics of a frame (docs/work-counters.md; with --repeat, each pass's median): exact on "
        "llvmpipe, where times are not.\n\n"
     << "| technique | pass |";
  std::string rule = "|---|---|";
  for (const WorkCounter& counter : kWorkCounters) {
    md << " " << counter.name << " |";
    rule += "---:|";
  }
  md << "\n" << rule << "\n";
  for (const auto& entry : c.entries) workRows(md, entry.record);
  workRows(md, c.groundTruth);
}

}  // namespace

const Record& baselineRecord(const Comparison& comparison) { return comparison.entries.front().record; }

std::string reportMarkdown(const Comparison& c) {
  const Record& first = baselineRecord(c);
  std::ostringstream md;
  md << "# " << markdownText(c.scene) << "\n\n"
     << "Screen " << first.width << "×" << first.height << ", shadow map " << first.shadowMap << "², "
     << first.depthFormat << "-bit depth, " << markdownText(first.backend) << ", " << first.repeat
     << " timed frame(s), medians. `× sm` is the technique's time (its passes, shadow map included) over `sm`'s in this run, "
     << (first.timing == TimingSource::Wall
             ? "by wall time between glFinish calls: this is a software rasterizer, whose timer queries miss the "
               "vertex work it does at draw time, and only ratios mean much here"
             : "by GL timer queries")
     << "; `× sm frame` is the whole frame's, G-buffer pass included, as the papers time it"
     << ". Errors are against the shadow-volume ground truth "
        "(docs/ground-truth-and-metrics.md, \"Error metrics\").\n\n";
  std::string header = "| technique |", rule = "|---|";
  for (const Metric& m : metricTable())
    if (m.shownIn(kReportColumn)) {
      header.append(" ").append(m.heading).append(" |");
      rule += "---:|";
    }
  md << header << "\n" << rule << "\n";
  for (const auto& entry : c.entries) {
    md << "| " << markdownCode(entry.record.technique) << " |";
    for (const Metric& m : metricTable())
      if (m.shownIn(kReportColumn)) md << " " << formatFixed(m.value(entry.record, &first), m.digits) << " |";
    md << "\n";
  }
  const Record& gt = c.groundTruth;
  md << "\nGround truth (" << markdownCode(gt.technique) << "): " << fixedMetric("technique_ms", gt, &first) << " ms, "
     << fixedMetric("x_sm", gt, &first) << "× sm; the whole frame including the CPU silhouette "
     << "extraction and upload took " << fixedMetric("cpu_ms", gt, &first) << " ms.\n\n"
     << "## Where the time goes\n\n"
     << "Each technique's passes, longest first: " << (first.timing == TimingSource::Wall ? "wall" : "GPU")
     << " ms (medians) and share of the technique's time. The G-buffer pass, shared by all, took "
     << formatFixed(first.gbufferMs, 2) << " ms.\n\n"
     << "| technique | ms | passes |\n|---|---:|---|\n";
  for (const auto& entry : c.entries) passRow(md, entry.record);
  passRow(md, gt);
  workSection(md, c);
  md << "\n![grid](grid.png)\n\n![speed against error](speed_vs_error.svg)\n";
  return md.str();
}

}  // namespace testbed
