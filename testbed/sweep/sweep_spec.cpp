// Sweep specs are hand-written like scene files, so every mistake is one line naming the
// file and the key path ("paper/x.json: rows[2].paper[1]: expected a number or null"):
// every value is read through the checked JSON reader (io/json_reader.h).
#include "testbed/sweep/sweep_spec.h"

#include <glob.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>

#include "testbed/core/error.h"
#include "testbed/harness/record.h"
#include "testbed/harness/sequence.h"
#include "testbed/io/json_input.h"
#include "testbed/io/json_reader.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Keys = std::vector<std::string>;

std::optional<double> numberOrNull(const JsonField& value) {
  if (value.json().is_null()) return std::nullopt;
  if (!value.json().is_number()) value.fail("expected a number or null, got " + value.brief());
  return value.number();
}

// WxH such as 1280x720, kept as written.
std::string sweepSizeText(const JsonField& value) {
  const std::string t = value.text();
  int w = 0, h = 0;
  if (t.find('x') == std::string::npos || std::sscanf(t.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1 ||
      std::to_string(w) + "x" + std::to_string(h) != t)
    value.fail("expected WxH such as 1280x720, got " + value.brief());
  return t;
}

std::string depthFormatWord(const JsonField& value) {
  static constexpr const char* kWords[] = {"16", "24", "32f"};
  return kWords[value.word({"16", "24", "32f"})];
}

// A technique id of the registry (or the ground truth's).
void checkSpecTechnique(const std::string& id, const JsonField& at) {
  if (id == kGroundTruthId) return;
  try {
    findTechnique(id);
  } catch (const InputError& error) {
    at.fail(error.what());
  }
}

std::string specTechniqueId(const JsonField& value) {
  std::string id = value.text();
  checkSpecTechnique(id, value);
  return id;
}

// "technique.name" of a known technique (the parameter itself is checked when planned).
void checkParameterName(const std::string& name, const JsonField& at) {
  const auto dot = name.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
    at.fail("expected a key \"technique.name\" (e.g. pcf.kernel)");
  checkSpecTechnique(name.substr(0, dot), at);
}

// A parameter's value as --set takes it.
std::string parameterValue(const JsonField& value) {
  const json& v = value.json();
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean() || v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (v.is_number_float()) return (value.number(), v.dump());
  value.fail("expected a number, string or boolean, got " + value.brief());
}

// Names that become part of output file names: checked here, not when the files are
// written after every cell has rendered.
void checkFileNamePart(const std::string& name, const JsonField& at) {
  if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-_") != std::string::npos)
    at.fail("expected lower-case letters, digits, '-' or '_' (it names the table's files), got " + briefJson(json(name)));
  if (name.size() > kMaxSweepNameLength)
    at.fail(std::to_string(name.size()) + " characters, more than the limit of " + std::to_string(kMaxSweepNameLength) +
            " (it names the table's files)");
}

// The keys a column, a row and the spec's "settings" share.
const Keys kSettingKeys = {"scene", "size", "shadow_map", "depth_format", "subdivide", "params"};

Keys withKeys(Keys keys, std::initializer_list<const char*> more) {
  keys.insert(keys.end(), more.begin(), more.end());
  return keys;
}

SweepSettings readSettings(const JsonField& object, const SweepSpec& spec) {
  SweepSettings s;
  if (const auto scene = object.find("scene")) {
    s.scene = scene->text();
    if (!spec.scenes.count(*s.scene)) scene->fail("'" + *s.scene + "' is not in \"scenes\"");
  }
  if (const auto size = object.find("size")) s.size = sweepSizeText(*size);
  if (const auto map = object.find("shadow_map")) s.shadowMap = map->integer(1, 16384);
  if (const auto format = object.find("depth_format")) s.depthFormat = depthFormatWord(*format);
  if (const auto subdivide = object.find("subdivide")) s.subdivide = subdivide->integer(0, 6);
  if (const auto params = object.find("params")) {
    if (!params->json().is_object()) params->fail("expected an object of \"technique.name\": value");
    for (const auto& name : params->keys()) {
      const JsonField value = (*params)[name];
      checkParameterName(name, value);
      s.params[name] = parameterValue(value);
    }
  }
  return s;
}

// A scene file's id in a folder, glob or list: its file name without ".json", in the
// characters ids may hold (they name the close-up figures' files).
std::string sceneIdOf(const fs::path& file) {
  std::string id;
  for (unsigned char c : file.stem().string()) id += std::isalnum(c) ? char(std::tolower(c)) : c == '_' ? '_' : '-';
  return id.substr(0, kMaxSweepNameLength);
}

bool isGlob(const std::string& text) { return text.find_first_of("*?[") != std::string::npos; }

// The scene files of a corpus folder: every *.json directly in it but the corpus's
// manifest.json, in name order.
std::vector<fs::path> folderScenes(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.is_regular_file() && entry.path().extension() == ".json" && entry.path().filename() != "manifest.json")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// The files a glob matches, a corpus's manifest.json left out as in a folder.
std::vector<fs::path> globScenes(const std::string& pattern) {
  glob_t found{};
  std::vector<fs::path> files;
  if (glob(pattern.c_str(), 0, nullptr, &found) == 0)  // sorted by glob
    for (std::size_t i = 0; i < found.gl_pathc; ++i)
      if (fs::is_regular_file(found.gl_pathv[i]) && fs::path(found.gl_pathv[i]).filename() != "manifest.json")
        files.push_back(found.gl_pathv[i]);
  globfree(&found);
  return files;
}

// "scenes" as a folder, a glob or a list of files, folders and globs (paths relative to
// the spec), expanded into id → file in the order given. Every source must yield a scene.
std::map<std::string, fs::path> expandScenes(const JsonField& scenes, const fs::path& spec,
                                             std::vector<std::string>& order) {
  std::map<std::string, fs::path> out;
  const json single = json::array({scenes.json()});
  const JsonField list = scenes.json().is_array() ? scenes : JsonField(single, scenes.file(), "");
  const std::size_t n = list.arraySize();
  if (n == 0) scenes.fail("expected scene files, folders or globs, got an empty list");
  for (std::size_t i = 0; i < n; ++i) {
    const JsonField source = scenes.json().is_array() ? list[i] : scenes;
    const std::string text = source.text();
    fs::path path = text;
    if (path.is_relative()) path = spec.parent_path() / path;
    std::vector<fs::path> files;
    if (isGlob(text)) {
      files = globScenes(path.string());
      if (files.empty()) source.fail("'" + text + "' matches no scene file");
    } else if (fs::is_directory(path)) {
      files = folderScenes(path);
      if (files.empty()) source.fail("the folder " + path.string() + " holds no scene file (an empty corpus?)");
    } else if (fs::is_regular_file(path)) {
      files = {path};
    } else {
      source.fail("no such scene file or folder: " + path.string());
    }
    for (const auto& file : files) {
      const std::string id = sceneIdOf(file);
      if (id.empty()) source.fail("cannot name a scene after " + file.string());
      const fs::path absolute = fs::absolute(file).lexically_normal();
      const auto [it, fresh] = out.emplace(id, absolute);
      if (!fresh && it->second != absolute)
        source.fail("two scene files would both be called '" + id + "': " + it->second.string() + " and " +
                    absolute.string());
      if (fresh) order.push_back(id);
    }
  }
  return out;
}

// True for a metric whose value is a ratio to `sm` (x_sm): it has a value only beside a
// baseline, which a table's cell does not have (the table adds ×SM columns itself).
bool needsBaseline(const Metric& m) {
  Record probe;
  probe.gpu.totalMs = probe.wall.totalMs = probe.gbufferMs = 1;
  probe.error.emplace().softRmse = 1;
  probe.work.emplace();
  return !m.value(probe, nullptr) && m.value(probe, &probe);
}

// "reference", "area_samples" and "light_radius" of the spec's "settings".
SweepAreaLight areaLightOf(const JsonField& settings) {
  SweepAreaLight area;
  if (const auto reference = settings.find("reference")) {
    constexpr SweepReference kReferences[] = {SweepReference::Hard, SweepReference::Soft, SweepReference::Both,
                                              SweepReference::ByOutput};
    area.reference = kReferences[reference->word({"hard", "soft", "both", "by_output"})];
  }
  // Without a soft reference these would change nothing: a spec that names them means one.
  const bool hard = area.reference == SweepReference::Hard;
  if (const auto samples = settings.find("area_samples")) {
    if (hard) samples->fail("the spec's reference is hard: no area-light reference is rendered");
    area.samples = samples->integer(1, 4096);
  }
  if (const auto radiusField = settings.find("light_radius")) {
    if (hard) radiusField->fail("the spec's reference is hard: no area-light reference is rendered");
    const auto radius = numberOrNull(*radiusField);
    if (!radius || !(*radius > 0) || *radius > 1e6)
      radiusField->fail("expected a number in (0, 1e6] (spot: world units; directional: degrees below 90)");
    area.lightRadius = *radius;
  }
  return area;
}

// What the reference cannot serve: a soft measure without an area-light reference, and a
// soft reference over frames (the sequences compare with the hard ground truth only).
void checkAreaLight(const SweepSpec& spec, const JsonField& top) {
  const SweepReference reference = spec.area.reference;
  const Metric* measured = spec.measure.metric;
  const bool frames = top.has("frames");
  if (measured && measured->reference == MetricReference::Soft && reference == SweepReference::Hard)
    top.failAt("measure", "\"" + spec.measure.name + "\" is measured against the area-light reference, which "
                          "settings.reference \"hard\" does not render");
  if (measured && measured->reference == MetricReference::Soft && frames)
    top.failAt("measure", "\"" + spec.measure.name + "\" is measured against the area-light reference, which a spec "
                          "over \"frames\" does not render (sequences are compared with the hard ground truth)");
  if (frames && spec.area.refusesNoRadius())
    JsonField(top.json(), top.file(), "settings.reference")
        .fail(std::string(sweepReferenceName(reference)) +
              ": not available with \"frames\" (sequences are compared with the hard ground truth)");
}

SweepMeasure measureOf(const JsonField& value) {
  const std::string name = value.text();
  std::string known;
  for (const Metric& m : metricTable())
    if (!needsBaseline(m)) known += (known.empty() ? "" : ", ") + std::string(m.name);
  const auto found = findSweepMeasure(name);
  if (!found || (found->metric && !found->overFrames() && needsBaseline(*found->metric)))
    value.fail("expected a metric of the metric table (" + known +
               "), or over frames flicker, crawl, crawl_missed or METRIC.mean/.p95/.max, got " + value.brief() +
               (name.rfind("x_sm", 0) == 0 ? " (a ratio to sm: the table adds ×SM columns itself)" : ""));
  return *found;
}

// The product of `columns` with each value of the axis at `values`; `apply` sets a
// column's value and returns its label.
template <class Apply>
void multiplyAxis(std::vector<SweepColumn>& columns, const JsonField& values, Apply apply) {
  if (!values.json().is_array() || values.json().empty()) values.fail("expected a non-empty array of values");
  std::vector<SweepColumn> product;
  for (const auto& column : columns)
    for (std::size_t i = 0; i < values.arraySize(); ++i) {
      SweepColumn next = column;
      next.label += " · " + apply(next.set, values[i]);
      product.push_back(std::move(next));
      if (product.size() > kMaxSweepEntries)
        values.fail("the axes make more than " + std::to_string(kMaxSweepEntries) + " columns");
    }
  columns = std::move(product);
}

// "axes": the columns as the product scene × size × shadow_map × depth_format × subdivide
// (every scene of "scenes", in order; the other axes where given), each column labelled
// by its values.
std::vector<SweepColumn> axisColumns(const JsonField& axes, const std::vector<std::string>& sceneOrder) {
  axes.allowKeys({"size", "shadow_map", "depth_format", "subdivide", "comment"});
  std::vector<SweepColumn> columns;
  for (const auto& id : sceneOrder) {
    SweepColumn column{id, {}};
    column.set.scene = id;
    columns.push_back(column);
  }
  if (const auto values = axes.find("size"))
    multiplyAxis(columns, *values, [](SweepSettings& set, const JsonField& value) { return *(set.size = sweepSizeText(value)); });
  if (const auto values = axes.find("shadow_map"))
    multiplyAxis(columns, *values, [](SweepSettings& set, const JsonField& value) {
      set.shadowMap = value.integer(1, 16384);
      return std::to_string(*set.shadowMap) + "²";
    });
  if (const auto values = axes.find("depth_format"))
    multiplyAxis(columns, *values, [](SweepSettings& set, const JsonField& value) {
      set.depthFormat = depthFormatWord(value);
      return "depth " + *set.depthFormat;
    });
  if (const auto values = axes.find("subdivide"))
    multiplyAxis(columns, *values, [](SweepSettings& set, const JsonField& value) {
      set.subdivide = value.integer(0, 6);
      return "subdivide " + std::to_string(*set.subdivide);
    });
  return columns;
}

// A row with "vary": one row per combination of the values (keys in name order), each
// labelled "<label> name=value ...".
std::vector<SweepRow> varied(const SweepRow& row, const JsonField& vary) {
  if (!vary.json().is_object() || vary.json().empty()) vary.fail("expected an object of \"technique.name\": [values]");
  std::vector<SweepRow> rows = {row};
  for (const auto& name : vary.keys()) {
    const JsonField values = vary[name];
    checkParameterName(name, values);
    if (!values.json().is_array() || values.json().empty()) values.fail("expected a non-empty array of values");
    std::vector<SweepRow> product;
    for (const auto& base : rows)
      for (std::size_t i = 0; i < values.arraySize(); ++i) {
        SweepRow next = base;
        const std::string text = parameterValue(values[i]);
        next.set.params[name] = text;
        next.label.append(" ").append(name, name.find('.') + 1).append("=").append(text);
        product.push_back(std::move(next));
        if (product.size() > kMaxSweepRows) values.fail("more than " + std::to_string(kMaxSweepRows) + " rows");
      }
    rows = std::move(product);
  }
  return rows;
}

}  // namespace

bool SweepRow::measured(std::size_t column) const {
  if (notMeasured.empty()) return true;
  if (notMeasuredColumns.empty()) return false;
  return std::find(notMeasuredColumns.begin(), notMeasuredColumns.end(), column) == notMeasuredColumns.end();
}

namespace {

// The sequence figures by measure name: JSON pointer into Record::sequence, decimals.
struct TemporalFigure {
  const char* name;
  const char* pointer;
  int digits;
};
constexpr TemporalFigure kTemporalFigures[] = {
    {"flicker", "/temporal/flicker", 5},
    {"crawl", "/temporal/crawl_pct", 4},
    {"crawl_missed", "/temporal/crawl_missed_pct", 4},
};

}  // namespace

std::optional<SweepMeasure> findSweepMeasure(const std::string& name) {
  for (const auto& t : kTemporalFigures)
    if (name == t.name) return SweepMeasure{name, nullptr, t.pointer};
  for (const Metric& m : metricTable())  // first: names with a dot of their own (boundary_px.mean)
    if (m.name == name) return SweepMeasure{name, &m, ""};
  const auto dot = name.rfind('.');
  if (dot != std::string::npos) {
    const std::string statistic = name.substr(dot + 1);
    const Metric* m = nullptr;
    for (const Metric& candidate : metricTable())
      if (candidate.name == name.substr(0, dot)) m = &candidate;
    if (m && !m->path.empty() && (statistic == "mean" || statistic == "p95" || statistic == "max"))
      return SweepMeasure{name, m, "/series/" + std::string(m->name) + "/" + statistic};
  }
  return std::nullopt;
}

std::optional<double> SweepMeasure::value(const Record& record) const {
  if (!overFrames()) return metric->value(record, nullptr);
  if (!record.sequence) return std::nullopt;
  const json::json_pointer pointer(sequencePointer);
  if (!record.sequence->contains(pointer) || !record.sequence->at(pointer).is_number()) return std::nullopt;
  return record.sequence->at(pointer).get<double>();
}

std::string SweepMeasure::unit() const {
  if (metric) return std::string(metric->unit());
  return name == "flicker" ? "" : "%";
}

int SweepMeasure::digits() const {
  if (metric) return metric->digits;
  for (const auto& t : kTemporalFigures)
    if (name == t.name) return t.digits;
  return 4;
}

bool SweepMeasure::error() const { return !metric || metric->path.starts_with("/error/"); }

Better SweepMeasure::better() const { return metric ? metric->better : Better::Lower; }

const char* sweepReferenceName(SweepReference reference) {
  switch (reference) {
    case SweepReference::Hard: return "hard";
    case SweepReference::Soft: return "soft";
    case SweepReference::Both: return "both";
    case SweepReference::ByOutput: break;
  }
  return "by_output";
}

SweepSpec loadSweepSpec(const fs::path& file) { return parseSweepSpec(readJsonInput(file, kMaxSweepSpecBytes), file); }

namespace {

// "scenes" (and an expanded spec.json's "scene_order"): the scenes by id, and their order
// on the scene axis.
std::vector<std::string> readScenes(const JsonField& top, const fs::path& file, bool sceneFilesMustExist, SweepSpec& spec) {
  const JsonField scenes = top["scenes"];
  std::vector<std::string> order;
  if (scenes.json().is_string() || scenes.json().is_array()) {
    spec.scenes = expandScenes(scenes, file, order);
    // The expanded list is what the shards' identity covers: a scene added to the corpus
    // folder between two shards' runs makes them two specs, which merge refuses.
    spec.document["scenes"] = json::object();
    for (const auto& [id, path] : spec.scenes) spec.document["scenes"][id] = path.string();
    spec.document["scene_order"] = order;
    return order;
  }
  if (!scenes.json().is_object() || scenes.json().empty())
    scenes.fail("expected an object of id: scene file, a corpus folder, a glob or a list of them, not empty");
  if (const auto given = top.find("scene_order")) {  // an expanded spec.json, as a shard wrote it
    if (!given->json().is_array() || given->arraySize() != scenes.json().size()) given->fail("expected one id per scene");
    for (std::size_t i = 0; i < given->arraySize(); ++i) {
      order.push_back((*given)[i].text());
      if (!scenes.has(order.back())) (*given)[i].fail("not in \"scenes\"");
    }
  }
  for (const auto& id : scenes.keys()) {
    const JsonField path = scenes[id];
    if (!top.has("scene_order")) order.push_back(id);
    checkFileNamePart(id, path);  // it names the close-up figure's file
    fs::path scene = path.text();
    if (scene.is_relative()) scene = file.parent_path() / scene;
    if (sceneFilesMustExist && !fs::is_regular_file(scene)) path.fail("no such scene file: " + scene.string());
    spec.scenes[id] = fs::absolute(scene).lexically_normal();
  }
  return order;
}

// "frames": the syntax now; the range against each scene's frames when the sweep loads it.
std::string readFrames(const JsonField& value) {
  const std::string frames = value.text();
  Scene probe;
  auto all = std::make_shared<Animation>();
  all->frames = std::numeric_limits<int>::max();
  probe.animation = all;
  try {
    parseFrameRange(frames, probe);
  } catch (const InputError& error) {
    const std::string what = error.what();
    value.fail(what.find("outside") != std::string::npos ? frames + ": expected 0 <= A <= B"
                                                         : what.substr(std::string("--frames: ").size()));
  }
  return frames;
}

std::vector<SweepColumn> readColumns(const JsonField& columns, const SweepSpec& spec) {
  if (!columns.json().is_array() || columns.json().empty()) columns.fail("expected a non-empty array");
  if (columns.arraySize() > kMaxSweepColumns)
    columns.fail(std::to_string(columns.arraySize()) + " columns, more than the limit of " + std::to_string(kMaxSweepColumns));
  std::vector<SweepColumn> out;
  for (std::size_t i = 0; i < columns.arraySize(); ++i) {
    const JsonField column = columns[i];
    column.allowKeys(withKeys(kSettingKeys, {"label", "comment"}));
    out.push_back({column["label"].text(), readSettings(column, spec)});
  }
  return out;
}

// A row's "passes": the pass names its entry sums.
std::vector<std::string> readRowPasses(const JsonField& passes) {
  if (!passes.json().is_array() || passes.json().empty()) passes.fail("expected a non-empty array of pass names");
  std::vector<std::string> names;
  for (std::size_t p = 0; p < passes.arraySize(); ++p) {
    names.push_back(passes[p].text());
    // The entry is the sum of the passes: one named twice would count twice.
    if (std::count(names.begin(), names.end(), names.back()) > 1)
      passes[p].fail("\"" + names.back() + "\" is already in the list");
  }
  // "frame" holds the G-buffer and every pass of the technique: any of them beside it
  // would count twice.
  if (std::count(names.begin(), names.end(), "frame") == 1 &&
      names.size() > std::size_t(1 + std::count(names.begin(), names.end(), "shading")))
    passes.fail("\"frame\" is the whole frame already; only \"shading\" may join it");
  return names;
}

// One row as written ("vary" is expanded by the caller).
SweepRow readRow(const JsonField& row, const SweepSpec& spec, std::size_t& entries) {
  row.allowKeys(withKeys(kSettingKeys, {"label", "group", "techniques", "vary", "passes", "not_measured",
                                    "not_measured_columns", "paper", "comment"}));
  SweepRow parsed;
  if (const auto group = row.find("group")) parsed.group = group->text();
  if (const auto comment = row.find("comment")) comment->text();
  const JsonField techniques = row["techniques"];
  if (!techniques.json().is_array() || techniques.json().empty()) techniques.fail("expected a non-empty array of ids");
  entries += techniques.arraySize() * spec.columns.size();
  if (entries > kMaxSweepEntries)
    techniques.fail("the table reaches " + std::to_string(entries) + " cells here, more than the limit of " +
                    std::to_string(kMaxSweepEntries));
  for (std::size_t t = 0; t < techniques.arraySize(); ++t) parsed.techniques.push_back(specTechniqueId(techniques[t]));
  // Without a label a row is called after its techniques.
  if (const auto label = row.find("label")) parsed.label = label->text();
  else
    for (const auto& t : parsed.techniques) parsed.label += (parsed.label.empty() ? "" : " + ") + t;
  parsed.set = readSettings(row, spec);
  if (const auto passes = row.find("passes")) parsed.passes = readRowPasses(*passes);
  if (const auto reason = row.find("not_measured")) parsed.notMeasured = reason->text();
  if (const auto columns = row.find("not_measured_columns")) {
    if (parsed.notMeasured.empty()) columns->fail("needs \"not_measured\" (the reason)");
    if (!columns->json().is_array() || columns->json().empty())
      columns->fail("expected a non-empty array of column indices");
    for (std::size_t k = 0; k < columns->arraySize(); ++k)
      parsed.notMeasuredColumns.push_back(std::size_t((*columns)[k].integer(0, int(spec.columns.size()) - 1)));
  }
  // A study of one's own has no paper's figures: a row without "paper" has none.
  if (const auto paper = row.find("paper")) {
    paper->arrayOf(spec.columns.size(), "an array of " + std::to_string(spec.columns.size()) +
                                            " numbers or nulls (one per column)");
    for (std::size_t c = 0; c < spec.columns.size(); ++c) parsed.paper.push_back(numberOrNull((*paper)[c]));
  } else {
    parsed.paper.resize(spec.columns.size());
  }
  return parsed;
}

void readRows(const JsonField& top, SweepSpec& spec) {
  // "techniques": ["sm", "pcf"] is rows [{"techniques": ["sm"]}, {"techniques": ["pcf"]}].
  json shorthand = json::array();
  if (const auto techniques = top.find("techniques")) {
    if (!techniques->json().is_array() || techniques->json().empty())
      techniques->fail("expected a non-empty array of ids");
    for (std::size_t t = 0; t < techniques->arraySize(); ++t)
      shorthand.push_back({{"techniques", json::array({specTechniqueId((*techniques)[t])})}});
  }
  json rowsValue = shorthand;
  if (const auto rows = top.find("rows")) {
    if (!rows->json().is_array() || rows->json().empty()) rows->fail("expected a non-empty array");
    rowsValue = rows->json();
    rowsValue.insert(rowsValue.end(), shorthand.begin(), shorthand.end());
  }
  const JsonField rows(rowsValue, top.file(), keyPath(top.path(), "rows"));
  if (rowsValue.size() > kMaxSweepRows)
    rows.fail(std::to_string(rowsValue.size()) + " rows, more than the limit of " + std::to_string(kMaxSweepRows));
  std::size_t entries = 0;  // cells the table asks for, before equal ones are merged
  for (std::size_t i = 0; i < rowsValue.size(); ++i) {
    const JsonField row = rows[i];
    SweepRow parsed = readRow(row, spec, entries);
    const auto vary = row.find("vary");
    if (!vary) {
      spec.rows.push_back(std::move(parsed));
      continue;
    }
    if (row.has("paper")) vary->fail("a row with \"paper\" figures cannot vary (whose figures would they be?)");
    for (auto& one : varied(parsed, *vary)) spec.rows.push_back(std::move(one));
    if (spec.rows.size() > kMaxSweepRows) vary->fail("more than " + std::to_string(kMaxSweepRows) + " rows");
    entries = 0;
    for (const auto& made : spec.rows) entries += made.techniques.size() * spec.columns.size();
    if (entries > kMaxSweepEntries)
      vary->fail("the table reaches " + std::to_string(entries) + " cells here, more than the limit of " +
                 std::to_string(kMaxSweepEntries));
  }
}

SweepFigure readFigure(const JsonField& figure, const SweepSpec& spec) {
  figure.allowKeys({"column", "window", "comment"});
  SweepFigure out = spec.figure;
  if (const auto column = figure.find("column")) out.column = std::size_t(column->integer(0, int(spec.columns.size()) - 1));
  if (const auto w = figure.find("window")) {
    w->arrayOf(3, "[x, y, side] in pixels");
    out.window = std::array<int, 3>{(*w)[0].integer(0, 8192), (*w)[1].integer(0, 8192), (*w)[2].integer(4, 8192)};
  }
  return out;
}

}  // namespace

SweepSpec parseSweepSpec(const json& document, const fs::path& file, bool sceneFilesMustExist) {
  const JsonField top(document, file.string());
  SweepSpec spec;
  spec.file = file;
  spec.document = document;
  top.allowKeys({"name", "title", "citation", "comment", "note", "scenes", "scene_order", "settings", "measure",
                 "frames", "columns", "axes", "rows", "techniques", "figure", "differences"});
  for (const char* required : {"name", "scenes"}) top[required];
  if (top.has("columns") == top.has("axes"))
    top.failAt(top.has("columns") ? "axes" : "columns",
               top.has("columns") ? "give \"columns\" or \"axes\", not both" : "missing (required, or \"axes\")");
  if (!top.has("rows") && !top.has("techniques")) top.failAt("rows", "missing (required, or \"techniques\")");
  spec.name = top["name"].text();
  checkFileNamePart(spec.name, top["name"]);
  if (spec.name == "records" || spec.name == "sweep" || spec.name == "spec")
    top["name"].fail("\"" + spec.name + "\" is the name of a sweep output file");
  if (const auto citation = top.find("citation")) spec.citation = citation->text();
  if (const auto title = top.find("title")) spec.title = title->text();
  if (const auto note = top.find("note")) spec.note = note->text();
  if (const auto comment = top.find("comment")) comment->text();
  if (const auto differences = top.find("differences")) spec.differences = differences->boolean();

  const std::vector<std::string> sceneOrder = readScenes(top, file, sceneFilesMustExist, spec);
  if (const auto settings = top.find("settings")) {
    settings->allowKeys(withKeys(kSettingKeys, {"repeat", "reference", "area_samples", "light_radius"}));
    spec.settings = readSettings(*settings, spec);
    if (const auto repeat = settings->find("repeat")) spec.repeat = repeat->integer(1, 10000);
    spec.area = areaLightOf(*settings);
  }
  if (const auto measure = top.find("measure")) spec.measure = measureOf(*measure);
  checkAreaLight(spec, top);
  if (const auto frames = top.find("frames")) spec.frames = readFrames(*frames);
  if (spec.measure.overFrames() && !spec.frames)
    top.failAt("measure", "\"" + spec.measure.name + "\" is a figure over frames: the spec needs \"frames\" (all or A:B[:STEP])");

  if (const auto axes = top.find("axes")) spec.columns = axisColumns(*axes, sceneOrder);
  if (const auto columns = top.find("columns")) spec.columns = readColumns(*columns, spec);
  readRows(top, spec);
  if (const auto figure = top.find("figure")) spec.figure = readFigure(*figure, spec);
  return spec;
}

bool isHarnessPass(const std::string& pass) {
  return std::find(kHarnessPasses.begin(), kHarnessPasses.end(), pass) != kHarnessPasses.end();
}

}  // namespace testbed
