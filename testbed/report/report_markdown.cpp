#include <cmath>
#include <sstream>

#include "testbed/report/comparison.h"

#include "testbed/harness/frame_runner.h"

namespace testbed {
namespace {

std::string fixed(double value, int digits) {
  if (!std::isfinite(value)) return "–";
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(digits);
  out << value;
  return out.str();
}

std::string metric(const nlohmann::json& error, const char* key, int digits) {
  if (!error.is_object() || !error.contains(key) || error[key].is_null()) return "–";
  return fixed(error[key].get<double>(), digits);
}

// The whole frame as the papers time it: the G-buffer pass plus the technique (the
// shading of T.png runs on the CPU, untimed, and is left out of both sides).
double wholeFrameRatio(const Comparison& comparison, const nlohmann::json& record) {
  const nlohmann::json& baseline = comparison.entries.front().record;
  const double gbuffer = record.value("gbuffer_ms", 0.0), baselineGbuffer = baseline.value("gbuffer_ms", 0.0);
  const double whole = gbuffer + frameTimeMs(record), baselineWhole = baselineGbuffer + frameTimeMs(baseline);
  return baselineWhole > 0 ? whole / baselineWhole : NAN;
}

}  // namespace

double ratioToBaseline(const Comparison& comparison, const nlohmann::json& record) {
  const double baseline = frameTimeMs(comparison.entries.front().record);
  return baseline > 0 ? frameTimeMs(record) / baseline : NAN;
}

std::string reportMarkdown(const Comparison& c) {
  const nlohmann::json& first = c.entries.front().record;
  std::ostringstream md;
  md << "# " << c.scene << "\n\n"
     << "Screen " << first["size"][0] << "×" << first["size"][1] << ", shadow map " << first["shadow_map"] << "², "
     << first["depth_format"].get<std::string>() << "-bit depth, " << first["backend"].get<std::string>() << ", "
     << first["repeat"] << " timed frame(s), medians. `× sm` is the technique's time (its passes, shadow map included) over `sm`'s in this run, "
     << (first["timing"] == "wall"
             ? "by wall time between glFinish calls: this is a software rasterizer, whose timer queries miss the "
               "vertex work it does at draw time, and only ratios mean much here"
             : "by GL timer queries")
     << "; `× sm frame` is the whole frame's, G-buffer pass included, as the papers time it"
     << ". Errors are against the stencil shadow-volume ground truth (README, Error metrics).\n\n"
     << "| technique | GPU ms (queries) | wall ms | × sm | × sm frame | memory KiB | mismatch % | edge mismatch % | RMSE | "
        "leak % | overestimation % | boundary px mean | boundary px p95 | soft RMSE |\n"
     << "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& entry : c.entries) {
    const auto& r = entry.record;
    const auto& e = r["error"];
    md << "| `" << r["technique"].get<std::string>() << "` | " << fixed(r["gpu_ms"]["total"].get<double>(), 2)
       << " | " << fixed(r["wall_ms"]["total"].get<double>(), 2) << " | " << fixed(ratioToBaseline(c, r), 2) << " | "
       << fixed(wholeFrameRatio(c, r), 2) << " | " << fixed(r["memory_bytes"].get<double>() / 1024.0, 0) << " | " << metric(e, "mismatch_pct", 3) << " | "
       << metric(e, "edge_mismatch_pct", 2) << " | " << metric(e, "rmse", 4) << " | " << metric(e, "leak_pct", 3)
       << " | " << metric(e, "overestimation_pct", 3) << " | "
       << (e.contains("boundary_px") ? fixed(e["boundary_px"]["mean"].get<double>(), 3) : "–") << " | "
       << (e.contains("boundary_px") ? fixed(e["boundary_px"]["p95"].get<double>(), 3) : "–") << " | "
       << metric(e, "soft_rmse", 4) << " |\n";
  }
  const auto& gt = c.groundTruth;
  md << "\nGround truth (`" << gt["technique"].get<std::string>() << "`): " << fixed(frameTimeMs(gt), 2)
     << " ms, " << fixed(ratioToBaseline(c, gt), 2) << "× sm; the whole frame including the CPU silhouette "
     << "extraction and upload took " << fixed(gt["cpu_ms"].get<double>(), 1) << " ms.\n\n"
     << "![grid](grid.png)\n\n![speed against error](speed_vs_error.svg)\n";
  return md.str();
}

}  // namespace testbed
