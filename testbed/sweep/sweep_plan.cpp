#include "testbed/sweep/sweep_plan.h"

#include <optional>
#include <string_view>

#include "testbed/core/error.h"
#include "testbed/core/number_text.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

template <typename T>
std::optional<T> firstOf(std::initializer_list<const std::optional<T>*> levels) {
  for (const auto* level : levels)
    if (*level) return **level;
  return std::nullopt;
}

// Checks a cell's parameters against the technique's declared ones.
void validateParameters(const SweepCell& cell, const SweepSpec& spec, const std::string& where) {
  try {
    if (cell.technique == kGroundTruthId)
      resolveParameters(cell.technique, {}, cell.params);
    else
      resolveParameters(cell.technique, findTechnique(cell.technique).info->parameters, cell.params);
  } catch (const InputError& error) {
    throw InputError(spec.file.string() + ": " + where + ": " + error.what());
  }
}

}  // namespace

std::string SweepCell::frameKey() const {
  return scene + "|" + (subdivide ? std::to_string(*subdivide) : "-") + "|" + size + "|" +
         std::to_string(shadowMap) + "|" + depthFormat;
}

std::string SweepCell::truthKey() const {
  return scene + "|" + (subdivide ? std::to_string(*subdivide) : "-") + "|" + size;
}

std::vector<std::vector<std::pair<std::size_t, std::size_t>>> SweepPlan::readers() const {
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> out(cells.size());
  const std::size_t columns = entries.empty() ? 0 : entries.front().size();
  for (std::size_t c = 0; c < columns; ++c)
    for (std::size_t r = 0; r < entries.size(); ++r)
      for (std::size_t cell : entries[r][c])
        if (out[cell].empty() || out[cell].back() != std::pair{r, c}) out[cell].emplace_back(r, c);
  return out;
}

nlohmann::json SweepCell::toJson() const {
  nlohmann::json j = {{"scene", scene}, {"size", size}, {"shadow_map", shadowMap}, {"depth_format", depthFormat},
                      {"technique", technique}, {"params", params}};
  if (subdivide) j["subdivide"] = *subdivide;
  if (frames) j["frames"] = *frames;
  if (soft != SoftJudging::None) j["soft_reference"] = soft == SoftJudging::Required ? "required" : "where_radius";
  return j;
}

namespace {

// Which reference a technique's cell is judged against, by the spec's "reference" and, by
// default, the technique's declared output (technique.h OutputKind).
SoftJudging softJudging(const SweepSpec& spec, const std::string& technique) {
  if (technique == kGroundTruthId) return SoftJudging::None;
  switch (spec.area.reference) {
    case SweepReference::Hard: return SoftJudging::None;
    case SweepReference::Soft:
    case SweepReference::Both: return SoftJudging::Required;
    case SweepReference::ByOutput: break;
  }
  // Sequences are compared with the hard ground truth only (the spec refuses soft and both).
  if (spec.frames || findTechnique(technique).info->output != OutputKind::Filtered) return SoftJudging::None;
  return spec.area.lightRadius ? SoftJudging::Required : SoftJudging::WhereRadius;
}

}  // namespace

SweepPlan planSweep(const SweepSpec& spec, const SweepOverrides& overrides) {
  SweepPlan plan;
  plan.repeat = overrides.repeat.value_or(spec.repeat);
  std::map<std::string, std::size_t> index;  // cell JSON → cell
  auto add = [&](SweepCell cell) {
    const std::string key = cell.toJson().dump();
    const auto [it, fresh] = index.emplace(key, plan.cells.size());
    if (fresh) plan.cells.push_back(std::move(cell));
    return it->second;
  };
  std::map<std::string, std::size_t> truthOf;  // truth key → ground-truth cell
  plan.entries.assign(spec.rows.size(), std::vector<std::vector<std::size_t>>(spec.columns.size()));
  for (std::size_t c = 0; c < spec.columns.size(); ++c) {
    for (std::size_t r = 0; r < spec.rows.size(); ++r) {
      if (!spec.rows[r].measured(c)) continue;  // no cells: shown as "—" with the row's reason
      const SweepSettings& col = spec.columns[c].set;
      const SweepSettings& row = spec.rows[r].set;
      const SweepSettings& top = spec.settings;
      const std::string where = "rows[" + std::to_string(r) + "] × columns[" + std::to_string(c) + "]";
      SweepCell base;
      const auto scene = firstOf<std::string>({&col.scene, &row.scene, &top.scene});
      if (scene) base.scene = *scene;
      else if (spec.scenes.size() == 1) base.scene = spec.scenes.begin()->first;
      else
        throw InputError(spec.file.string() + ": " + where +
                         ": no scene (give \"scene\" in the row, the column or \"settings\": the spec has several)");
      base.subdivide = firstOf<int>({&col.subdivide, &row.subdivide, &top.subdivide});
      base.size = overrides.size.value_or(firstOf<std::string>({&col.size, &row.size, &top.size}).value_or("1280x720"));
      base.shadowMap = overrides.shadowMap.value_or(firstOf<int>({&col.shadowMap, &row.shadowMap, &top.shadowMap}).value_or(1024));
      base.depthFormat =
          overrides.depthFormat.value_or(firstOf<std::string>({&col.depthFormat, &row.depthFormat, &top.depthFormat}).value_or("16"));
      base.frames = spec.frames;

      const auto truth = truthOf.find(base.truthKey());
      if (truth == truthOf.end()) {
        SweepCell gt = base;
        gt.technique = kGroundTruthId;
        gt.truthCell = plan.cells.size();
        truthOf[base.truthKey()] = add(gt);
      }
      base.truthCell = truthOf.at(base.truthKey());
      for (const auto& technique : spec.rows[r].techniques) {
        SweepCell cell = base;
        cell.technique = technique;
        cell.soft = softJudging(spec, technique);
        const std::string prefix = technique + ".";
        for (const auto* level : {&top.params, &row.params, &col.params})  // later levels win
          for (const auto& [name, value] : *level)
            if (name.compare(0, prefix.size(), prefix) == 0) cell.params[name.substr(prefix.size())] = value;
        validateParameters(cell, spec, where);
        plan.entries[r][c].push_back(add(std::move(cell)));
      }
    }
  }
  return plan;
}

Shard parseShard(const std::string& text) {
  Shard shard;
  const auto slash = text.find('/');
  const auto index = wholeNumber<int>(std::string_view(text).substr(0, slash));
  const auto count = slash == std::string::npos ? std::nullopt : wholeNumber<int>(std::string_view(text).substr(slash + 1));
  if (index) shard.index = *index;
  if (count) shard.count = *count;
  if (!index || !count || shard.count < 1 || shard.count > 100000 || shard.index < 1 || shard.index > shard.count)
    throw InputError("--shard: expected K/N with 1 <= K <= N (e.g. 2/4), got '" + text + "'");
  return shard;
}

std::string fingerprint(const std::string& bytes) {
  std::uint64_t hash = 1469598103934665603ull;
  for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace testbed
