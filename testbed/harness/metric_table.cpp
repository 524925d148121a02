#include "testbed/harness/metric_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "testbed/harness/record.h"

namespace testbed {
namespace {

using Value = std::optional<double>;

Value finite(double value) { return std::isfinite(value) ? Value(value) : std::nullopt; }

// The technique's time and the whole frame's (G-buffer added), in the record's measure.
double techniqueMs(const Record& r) { return r.timed().totalMs; }
double wholeFrameMs(const Record& r) { return r.gbufferMs + r.timed().totalMs; }

Value ratio(double value, double baseline) { return baseline > 0 ? finite(value / baseline) : std::nullopt; }

template <double ErrorMetrics::*Member>
Value errorValue(const Record& r, const Record*) {
  return r.error ? Value((*r.error).*Member) : std::nullopt;
}
template <double ErrorMetrics::*Member>
void storeError(Record& r, double value) {
  if (!r.error) r.error.emplace();
  (*r.error).*Member = value;
}

// The soft metrics: absent (null) without an area-light reference.
template <std::optional<double> ErrorMetrics::*Member>
Value softValue(const Record& r, const Record*) {
  return r.error ? (*r.error).*Member : std::nullopt;
}
template <std::optional<double> ErrorMetrics::*Member>
void storeSoft(Record& r, double value) {
  if (!r.error) r.error.emplace();
  (*r.error).*Member = value;
}

constexpr unsigned kNone = 0;

// A work counter's frame total (the sum over the passes); none where nothing was counted.
template <std::size_t Counter>
Value workTotal(const Record& r, const Record*) {
  return r.work ? Value(double(r.work->total[Counter])) : std::nullopt;
}
static_assert(kWorkCounters.size() == 5, "one metric per work counter below");

// Table order is report.md's column order and the order of check's findings.
const std::vector<Metric> kTable = {
    {"gpu_ms.total", "/gpu_ms/total", "GPU ms (queries)", "", " ms", 2, CheckRule::None, 0, Better::Lower,
     kReportColumn | kCounter, false, false, [](const Record& r, const Record*) -> Value { return r.gpu.totalMs; },
     [](Record& r, double v) { r.gpu.totalMs = v; }},
    {"wall_ms.total", "/wall_ms/total", "wall ms", "", " ms", 2, CheckRule::None, 0, Better::Lower,
     kReportColumn | kCounter, false, false, [](const Record& r, const Record*) -> Value { return r.wall.totalMs; },
     [](Record& r, double v) { r.wall.totalMs = v; }},
    // The technique's frame in the measure the record's `timing` names.
    {"technique_ms", "", "ms", "", " ms", 2, CheckRule::None, 0, Better::Lower, kBrief | kCarried, false, false,
     [](const Record& r, const Record*) -> Value { return techniqueMs(r); }, nullptr, MetricReference::None, {}, "gpu_ms.total wall_ms.total"},
    {"x_sm", "", "× sm", "", "x sm", 2, CheckRule::Speed, 0, Better::Lower, kReportColumn | kBrief | kCounter, false,
     false,
     [](const Record& r, const Record* sm) -> Value { return sm ? ratio(techniqueMs(r), techniqueMs(*sm)) : std::nullopt; },
     nullptr, MetricReference::None, {}, "technique_ms"},
    // The whole frame as the papers time it: the G-buffer pass plus the technique's.
    {"x_sm_frame", "", "× sm frame", "", "x sm frame", 2, CheckRule::None, 0, Better::Lower, kReportColumn | kCounter,
     false, false,
     [](const Record& r, const Record* sm) -> Value { return sm ? ratio(wholeFrameMs(r), wholeFrameMs(*sm)) : std::nullopt; },
     nullptr, MetricReference::None, {}, "frame_ms"},
    {"frame_ms", "", "frame ms", "", " ms", 2, CheckRule::None, 0, Better::Lower, kSweepMeasure | kCarried, false, false,
     [](const Record& r, const Record*) -> Value { return wholeFrameMs(r); }, nullptr, MetricReference::None, {}, "gbuffer_ms technique_ms"},
    {"fps", "", "fps", "", " fps", 2, CheckRule::None, 0, Better::Higher, kSweepMeasure | kCarried, false, false,
     [](const Record& r, const Record*) -> Value { return wholeFrameMs(r) > 0 ? finite(1000.0 / wholeFrameMs(r)) : std::nullopt; },
     nullptr, MetricReference::None, {}, "frame_ms"},
    {"cpu_ms", "/cpu_ms", "CPU ms", "", " ms", 1, CheckRule::None, 0, Better::Lower, kCounter, false, false,
     [](const Record& r, const Record*) -> Value { return r.cpuMs; }, [](Record& r, double v) { r.cpuMs = v; }},
    {"gbuffer_ms", "/gbuffer_ms", "G-buffer ms", "", " ms", 2, CheckRule::None, 0, Better::Lower, kNone, false, false,
     [](const Record& r, const Record*) -> Value { return r.gbufferMs; }, [](Record& r, double v) { r.gbufferMs = v; }},
    {"memory_bytes", "/memory_bytes", "memory bytes", "", " bytes", 0, CheckRule::Exact, 0, Better::Lower, kCounter, true,
     false, [](const Record& r, const Record*) -> Value { return double(r.memoryBytes); },
     [](Record& r, double v) { r.memoryBytes = std::uint64_t(v); }},
    {"memory_kib", "", "memory KiB", "", " KiB", 0, CheckRule::None, 0, Better::Lower, kReportColumn | kCarried, false, false,
     [](const Record& r, const Record*) -> Value { return double(r.memoryBytes) / 1024.0; }, nullptr, MetricReference::None, {}, "memory_bytes"},
    {"memory_mb", "", "memory MB", "", " MB", 2, CheckRule::None, 0, Better::Lower, kSweepMeasure | kCarried, false, false,
     [](const Record& r, const Record*) -> Value { return double(r.memoryBytes) / (1024.0 * 1024.0); }, nullptr, MetricReference::None, {}, "memory_bytes"},
    // The work block's totals (docs/work-counters.md); check compares them pass by pass.
    {"vertex_invocations", "", "vertex invocations", "", " invocations", 0, CheckRule::Work, 0, Better::Lower,
     kCounter, true, true, workTotal<0>, nullptr},
    {"fragment_invocations", "", "fragment invocations", "", " invocations", 0, CheckRule::Work, 0, Better::Lower,
     kCounter, true, true, workTotal<1>, nullptr},
    {"compute_invocations", "", "compute invocations", "", " invocations", 0, CheckRule::Work, 0, Better::Lower,
     kCounter, true, true, workTotal<2>, nullptr},
    {"primitives_submitted", "", "primitives submitted", "", " primitives", 0, CheckRule::Work, 0, Better::Lower,
     kCounter, true, true, workTotal<3>, nullptr},
    {"clipping_input_primitives", "", "clipping input primitives", "", " primitives", 0, CheckRule::Work, 0,
     Better::Lower, kCounter, true, true, workTotal<4>, nullptr},
    // The shader invocations of all three stages in thousands: report.md's one work column.
    {"invocations_k", "", "invocations (k)", "", "k invocations", 1, CheckRule::None, 0, Better::Lower,
     kReportColumn | kCarried, false, true,
     [](const Record& r, const Record*) -> Value {
       return r.work ? Value(double(r.work->total[0] + r.work->total[1] + r.work->total[2]) / 1000.0) : std::nullopt;
     },
     nullptr, MetricReference::None, {}, "vertex_invocations fragment_invocations compute_invocations"},
    // The error block (docs/ground-truth-and-metrics.md "Error metrics"); floors: 0.01 percentage
    // points, 0.001 RMSE, 0.01 px.
    {"mismatch_pct", "/error/mismatch_pct", "mismatch %", "mismatch", "%", 3, CheckRule::Error, 0.01, Better::Lower,
     kReportColumn | kBrief, false, false, errorValue<&ErrorMetrics::mismatchPct>,
     storeError<&ErrorMetrics::mismatchPct>, MetricReference::Hard, "% of receivers in the wrong binary state"},
    {"edge_mismatch_pct", "/error/edge_mismatch_pct", "edge mismatch %", "edge mismatch", "%", 2, CheckRule::Error, 0.01,
     Better::Lower, kReportColumn, false, false, errorValue<&ErrorMetrics::edgeMismatchPct>,
     storeError<&ErrorMetrics::edgeMismatchPct>, MetricReference::Hard, "% wrong within 3 px of a ground-truth boundary"},
    {"rmse", "/error/rmse", "RMSE", "RMSE", "", 4, CheckRule::Error, 0.001, Better::Lower, kReportColumn, false, false,
     errorValue<&ErrorMetrics::rmse>, storeError<&ErrorMetrics::rmse>, MetricReference::Hard, "RMSE of visibility"},
    {"leak_pct", "/error/leak_pct", "leak %", "leak", "%", 3, CheckRule::Error, 0.01, Better::Lower,
     kReportColumn | kBrief, false, false, errorValue<&ErrorMetrics::leakPct>, storeError<&ErrorMetrics::leakPct>,
     MetricReference::Hard, "% of deep-shadow receivers lit"},
    {"overestimation_pct", "/error/overestimation_pct", "overestimation %", "overestimation", "%", 3, CheckRule::Error,
     0.01, Better::Lower, kReportColumn, false, false, errorValue<&ErrorMetrics::overestimationPct>,
     storeError<&ErrorMetrics::overestimationPct>, MetricReference::Hard, "% of deep-lit receivers shadowed"},
    {"boundary_px.mean", "/error/boundary_px/mean", "boundary px mean", "boundary", " px", 3, CheckRule::Error, 0.01,
     Better::Lower, kReportColumn | kBrief, false, false, errorValue<&ErrorMetrics::boundaryMean>,
     storeError<&ErrorMetrics::boundaryMean>, MetricReference::Hard, "mean boundary distance, px"},
    {"boundary_px.p95", "/error/boundary_px/p95", "boundary px p95", "boundary p95", " px", 3, CheckRule::None, 0,
     Better::Lower, kReportColumn, false, false, errorValue<&ErrorMetrics::boundaryP95>,
     storeError<&ErrorMetrics::boundaryP95>, MetricReference::Hard, "95th percentile boundary distance, px"},
    {"soft_rmse", "/error/soft_rmse", "soft RMSE", "soft RMSE", "", 4, CheckRule::Error, 0.001, Better::Lower,
     kReportColumn | kBrief, false, true,
     softValue<&ErrorMetrics::softRmse>,
     storeSoft<&ErrorMetrics::softRmse>, MetricReference::Soft, "RMSE against the area-light reference"},
    // Penumbra metrics against the area-light reference (kPenumbraEpsilon, metrics.h).
    {"soft_penumbra_mae", "/error/soft_penumbra_mae", "soft MAE penumbra", "penumbra MAE", "", 4, CheckRule::Error, 0.001,
     Better::Lower, kReportColumn | kBrief, false, false, softValue<&ErrorMetrics::softPenumbraMae>,
     storeSoft<&ErrorMetrics::softPenumbraMae>, MetricReference::Soft, "mean absolute error in the reference's penumbra"},
    {"soft_outside_mae", "/error/soft_outside_mae", "soft MAE outside penumbra", "", "", 4, CheckRule::Error, 0.001,
     Better::Lower, kReportColumn, false, false, softValue<&ErrorMetrics::softOutsideMae>,
     storeSoft<&ErrorMetrics::softOutsideMae>, MetricReference::Soft, "mean absolute error outside the reference's penumbra"},
    {"soft_umbra_leak", "/error/soft_umbra_leak", "soft umbra leak", "", "", 4, CheckRule::Error, 0.001, Better::Lower,
     kReportColumn, false, false, softValue<&ErrorMetrics::softUmbraLeak>, storeSoft<&ErrorMetrics::softUmbraLeak>,
     MetricReference::Soft, "mean visibility in the reference's umbra (light leaked)"},
};

}  // namespace

std::string_view Metric::unit() const {
  const auto start = suffix.find_first_not_of(' ');
  return start == std::string_view::npos ? std::string_view{} : suffix.substr(start);
}

std::span<const Metric> metricTable() { return kTable; }

std::string recordPath(const Metric& m) {
  if (!m.path.empty()) return std::string(m.path);
  if (m.check == CheckRule::Work) return "/work/total/" + std::string(m.name);  // record.cpp countsJson
  return m.shownIn(kCarried) ? "/derived/" + std::string(m.name) : std::string();
}

std::vector<std::string_view> inputsOf(const Metric& m) {
  std::vector<std::string_view> out;
  for (std::size_t at = 0; at < m.from.size();) {
    const std::size_t end = std::min(m.from.find(' ', at), m.from.size());
    out.push_back(m.from.substr(at, end - at));
    at = end + 1;
  }
  return out;
}

std::vector<std::string_view> useNames(unsigned uses) {
  static constexpr std::pair<MetricUse, std::string_view> kNames[] = {
      {kReportColumn, "report_column"}, {kBrief, "brief"}, {kCounter, "counter"}, {kSweepMeasure, "sweep_measure"},
      {kCarried, "carried"}};
  std::vector<std::string_view> out;
  for (const auto& [use, name] : kNames)
    if (uses & use) out.push_back(name);
  return out;
}

std::string_view referenceName(MetricReference reference) {
  switch (reference) {
    case MetricReference::Hard: return "hard";
    case MetricReference::Soft: return "soft";
    case MetricReference::None: break;
  }
  return "";
}

const Metric* findMetric(std::string_view name, MetricUse use) {
  for (const Metric& m : kTable)
    if (m.name == name && m.shownIn(use)) return &m;
  return nullptr;
}

const Metric& metric(std::string_view name) {
  for (const Metric& m : kTable)
    if (m.name == name) return m;
  throw std::logic_error("no metric '" + std::string(name) + "' in the metric table");
}

std::string formatFixed(std::optional<double> value, int digits) {
  if (!value || !std::isfinite(*value)) return "–";
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, *value);
  return text;
}

std::string briefSummary(const Record& record, const Record* sm, std::string_view separator) {
  std::string line;
  for (const Metric& m : kTable) {
    if (!m.shownIn(kBrief)) continue;
    const Value v = m.value(record, sm);
    if (!v) continue;
    char number[32];
    std::snprintf(number, sizeof number, "%.3g", *v);
    if (!line.empty()) line += separator;
    if (!m.brief.empty()) line.append(m.brief).append(" ");
    line.append(number).append(m.suffix);
  }
  return line;
}

}  // namespace testbed
