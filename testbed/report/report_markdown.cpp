#include <sstream>

#include "testbed/harness/metric_table.h"
#include "testbed/report/comparison.h"

namespace testbed {
namespace {

std::string fixedMetric(const char* name, const Record& record, const Record* sm) {
  const Metric& m = metric(name);
  return formatFixed(m.value(record, sm), m.digits);
}

}  // namespace

const Record& baselineRecord(const Comparison& comparison) { return comparison.entries.front().record; }

std::string reportMarkdown(const Comparison& c) {
  const Record& first = baselineRecord(c);
  std::ostringstream md;
  md << "# " << c.scene << "\n\n"
     << "Screen " << first.width << "×" << first.height << ", shadow map " << first.shadowMap << "², "
     << first.depthFormat << "-bit depth, " << first.backend << ", " << first.repeat
     << " timed frame(s), medians. `× sm` is the technique's time (its passes, shadow map included) over `sm`'s in this run, "
     << (first.timing == TimingSource::Wall
             ? "by wall time between glFinish calls: this is a software rasterizer, whose timer queries miss the "
               "vertex work it does at draw time, and only ratios mean much here"
             : "by GL timer queries")
     << "; `× sm frame` is the whole frame's, G-buffer pass included, as the papers time it"
     << ". Errors are against the stencil shadow-volume ground truth (README, Error metrics).\n\n";
  std::string header = "| technique |", rule = "|---|";
  for (const Metric& m : metricTable())
    if (m.shownIn(kReportColumn)) {
      header.append(" ").append(m.heading).append(" |");
      rule += "---:|";
    }
  md << header << "\n" << rule << "\n";
  for (const auto& entry : c.entries) {
    md << "| `" << entry.record.technique << "` |";
    for (const Metric& m : metricTable())
      if (m.shownIn(kReportColumn)) md << " " << formatFixed(m.value(entry.record, &first), m.digits) << " |";
    md << "\n";
  }
  const Record& gt = c.groundTruth;
  md << "\nGround truth (`" << gt.technique << "`): " << fixedMetric("technique_ms", gt, &first) << " ms, "
     << fixedMetric("x_sm", gt, &first) << "× sm; the whole frame including the CPU silhouette "
     << "extraction and upload took " << fixedMetric("cpu_ms", gt, &first) << " ms.\n\n"
     << "![grid](grid.png)\n\n![speed against error](speed_vs_error.svg)\n";
  return md.str();
}

}  // namespace testbed
