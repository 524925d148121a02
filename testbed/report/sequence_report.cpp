#include "testbed/report/sequence_report.h"

#include <sstream>

#include "testbed/core/markdown_text.h"
#include "testbed/harness/metric_table.h"

namespace testbed {
namespace {

std::optional<double> at(const nlohmann::json& json, const std::string& pointer) {
  const nlohmann::json::json_pointer p(pointer);
  if (!json.contains(p) || !json.at(p).is_number()) return std::nullopt;
  return json.at(p).get<double>();
}

}  // namespace

std::string sequenceMarkdown(const std::string& scene, const std::vector<nlohmann::json>& records) {
  std::vector<const Metric*> columns;
  for (const Metric& m : metricTable())
    if (!m.path.empty() && m.shownIn(kReportColumn)) columns.push_back(&m);
  std::ostringstream out;
  out << "# " << markdownText(scene) << ": sequence\n\n";
  if (!records.empty()) {
    const auto& f = records.front().at("frames");
    out << "Frames " << f.at("first") << ".." << f.at("last") << " step " << f.at("step") << " (" << f.at("count")
        << " frames), " << records.front().at("width") << "x" << records.front().at("height") << ", shadow map "
        << records.front().at("shadow_map") << "², light set-up fitted per frame. Flicker and crawl: "
        << "docs/motion.md \"Temporal metrics\" (frame t against the previous frame's scene seen through "
        << "frame t's camera; held renders: frame pairs that needed that extra render because the camera "
        << "moved; moved pixels: receivers left unpaired because an object moved); other columns: mean / p95 / "
        << "max over frames.\n\n";
  }
  out << "| technique | flicker | crawl % | crawl missed % | stable pairs | moved pixels | held renders |";
  for (const Metric* m : columns) out << " " << m->heading << " |";
  out << "\n|---|---:|---:|---:|---:|---:|---:|";
  for (std::size_t i = 0; i < columns.size(); ++i) out << "---:|";
  out << "\n";
  for (const auto& r : records) {
    out << "| " << markdownText(r.at("technique").get<std::string>()) << " | "
        << formatFixed(at(r, "/temporal/flicker"), 5) << " | " << formatFixed(at(r, "/temporal/crawl_pct"), 4)
        << " | " << formatFixed(at(r, "/temporal/crawl_missed_pct"), 4) << " | "
        << formatFixed(at(r, "/temporal/stable_pairs"), 0) << " | " << formatFixed(at(r, "/temporal/moved_pixels"), 0)
        << " | " << formatFixed(at(r, "/temporal/held_renders"), 0) << " |";
    for (const Metric* m : columns) {
      const std::string base = "/series/" + std::string(m->name);
      out << " " << formatFixed(at(r, base + "/mean"), m->digits) << " / "
          << formatFixed(at(r, base + "/p95"), m->digits) << " / " << formatFixed(at(r, base + "/max"), m->digits)
          << " |";
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace testbed
