#include "testbed/app/sweep_report.h"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "testbed/app/commands.h"
#include "testbed/app/python_script.h"
#include "testbed/app/work_folder.h"
#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/io/json_reader.h"
#include "testbed/report/report_html.h"
#include "testbed/sweep/sweep_figure.h"


namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// "osmesa: llvmpipe (LLVM 15.0.6, 256 bits)" → "osmesa-llvmpipe-llvm-15-0-6-256-bits".
std::string slug(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c)) out += char(std::tolower(c));
    else if (!out.empty() && out.back() != '-') out += '-';
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out.substr(0, 48);
}

// scripts/sweep_plot.py draws the table in a private folder; its plot is staged beside the
// table, so a failing plot leaves nothing committed rather than tables without their plots.
void stagePlot(OutputFiles& files, const std::string& name, const std::string& tableJson) {
  const WorkFolder work("testbed-plot");
  const fs::path table = work.write(name + ".json", tableJson);
  runPythonScript("sweep_plot.py", {table.string()}, (files.directory() / (name + ".json")).string());
  for (const char* extension : {".png", ".svg"})
    files.writeText(name + extension, WorkFolder::read(work.path() / (name + extension)));
}

// What the records' errors were taken against (docs/paper-runs.md "Reference"), for the
// table's header: the spec's reference and, where cells are judged by the area light, its
// samples and radius.
std::string referenceDescription(const SweepSpec& spec, const SweepPlan& plan) {
  const bool area = std::any_of(plan.cells.begin(), plan.cells.end(),
                                [](const SweepCell& cell) { return cell.soft != SoftJudging::None; });
  std::string text = sweepReferenceName(spec.area.reference);
  text += spec.area.reference == SweepReference::ByOutput
              ? ": hard outputs against the hard ground truth, filtered ones against the area-light reference too"
              : area ? ": every technique against the hard ground truth and the area-light reference"
                     : ": the hard ground truth";
  if (!area) return text;
  std::ostringstream radius;
  if (spec.area.lightRadius) radius << "light radius " << *spec.area.lightRadius;
  else radius << "each scene's light radius";
  return text + " (" + std::to_string(spec.area.samples) + " samples, " + radius.str() + ")";
}

}  // namespace

std::string buildFingerprint() {
  std::ifstream in("/proc/self/exe", std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return fingerprint(bytes.str());
}

std::string hostDescription() {
  char host[256] = {0};
  gethostname(host, sizeof host - 1);
  std::string cpu;
  std::ifstream info("/proc/cpuinfo");
  for (std::string line; cpu.empty() && std::getline(info, line);)
    if (line.rfind("model name", 0) == 0) cpu = line.substr(line.find(':') + 2);
  return std::string(host) + " (" + (cpu.empty() ? "unknown CPU" : cpu) + ", " +
         std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " cores)";
}

json overridesJson(const SweepOverrides& o) {
  json j = json::object();
  if (o.size) j["size"] = *o.size;
  if (o.shadowMap) j["shadow_map"] = *o.shadowMap;
  if (o.depthFormat) j["depth_format"] = *o.depthFormat;
  if (o.repeat) j["repeat"] = *o.repeat;
  return j;
}

// The overrides a sweep.json records, read by the checked JSON reader's rules; `where`
// is their place ("<dir>/sweep.json: overrides"), to which each key's path is appended.
SweepOverrides overridesFromJson(const json& j, const std::string& where) {
  const JsonField overrides(j, "", where);
  overrides.allowKeys({"size", "shadow_map", "depth_format", "repeat"});
  SweepOverrides o;
  if (const auto size = overrides.find("size")) {
    o.size = size->text();
    try {
      parseSize(*o.size);
    } catch (const InputError& error) {
      size->fail(error.what());
    }
  }
  if (const auto map = overrides.find("shadow_map")) o.shadowMap = map->integer(1, 16384);
  if (const auto format = overrides.find("depth_format")) {
    static constexpr const char* kFormats[] = {"16", "24", "32f"};
    o.depthFormat = kFormats[format->word({"16", "24", "32f"})];
  }
  if (const auto repeat = overrides.find("repeat")) o.repeat = repeat->integer(1, 10000);
  return o;
}

std::string specFingerprint(const json& document, const json& overrides) {
  return fingerprint(document.dump() + "\n" + overrides.dump());
}

std::vector<std::size_t> figureCells(const SweepSpec& spec, const SweepPlan& plan) {
  std::vector<std::size_t> cells;
  std::set<std::size_t> seen;
  for (std::size_t r = 0; r < spec.rows.size(); ++r)
    for (std::size_t cell : plan.entries[r][spec.figure.column])
      for (std::size_t c : {plan.cells[cell].truthCell, cell})
        if (seen.insert(c).second) cells.push_back(c);
  return cells;
}

std::string figureFileName(std::size_t cell, const char* extension) {
  return "figure-cell-" + std::to_string(cell) + "." + extension;
}

void stageSweepReport(OutputFiles& files, const SweepSpec& spec, const SweepPlan& plan, const std::vector<Record>& records,
                      const SweepHeader& header, const std::map<std::size_t, FigureImages>& figureImages, bool plots) {
  std::map<std::string, std::map<std::size_t, Record>> byBackend;
  for (const auto& record : records) byBackend[record.backend][record.cell.value()] = record;
  if (byBackend.empty()) byBackend[""];  // an empty table still shows the paper's figures
  std::vector<std::pair<std::string, nlohmann::json>> pageTables;  // index.html's tables
  for (const auto& [backend, cells] : byBackend) {
    const std::string name = byBackend.size() == 1 ? spec.name : spec.name + "." + slug(backend);
    SweepHeader withBackend = header;
    withBackend.emplace_back("reference", referenceDescription(spec, plan));
    for (auto& [key, value] : withBackend)
      if (key == "backend") value = backend;
    const SweepTable table = buildSweepTable(spec, plan, cells);
    files.writeText(name + ".md", sweepTableMarkdown(table, withBackend));
    pageTables.emplace_back(name, sweepTableJson(table, withBackend));
    files.writeText(name + ".json", pageTables.back().second.dump(2) + "\n");
    if (plots) stagePlot(files, name, pageTables.back().second.dump(2) + "\n");
  }
  // One close-up figure per frame set-up of the figure column (a scene, in the papers).
  std::map<std::size_t, std::vector<std::size_t>> byTruth;
  for (std::size_t cell : figureCells(spec, plan))
    if (plan.cells[cell].technique != kGroundTruthId) byTruth[plan.cells[cell].truthCell].push_back(cell);
  std::set<std::string> names;
  for (const auto& [truth, cells] : byTruth) {
    if (!figureImages.count(truth)) continue;
    std::vector<CloseUpTile> tiles;
    for (std::size_t cell : cells) {
      const auto it = figureImages.find(cell);
      if (it == figureImages.end()) continue;
      std::string label = plan.cells[cell].technique;
      for (const auto& [k, v] : plan.cells[cell].params) label.append(" ").append(k).append("=").append(v);
      tiles.push_back({label, &it->second.visibility, &it->second.shaded});
    }
    const FigureImages& gt = figureImages.at(truth);
    const CloseUpFigure figure = closeUpFigure({"shadow volumes (ground truth)", &gt.visibility, &gt.shaded}, tiles,
                                               spec.figure.window);
    std::string name = spec.name + "-closeup-" + plan.cells[truth].scene;
    while (!names.insert(name).second) name.append("-").append(std::to_string(truth));
    files.writeImage(name + ".png", figure.image);
  }
  files.writeText("index.html", sweepHtml(spec.name, pageTables, plan.entries, records, {names.begin(), names.end()}, plots));
}


}  // namespace testbed
