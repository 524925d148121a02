// Sweep specs are hand-written like scene files, so every mistake is one line naming the
// file and the key path ("paper/x.json: rows[2].paper[1]: expected a number or null").
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
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class SpecReader {
 public:
  explicit SpecReader(const fs::path& file) : file_(file) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_.string() + ": " + (key.empty() ? "" : key + ": ") + what);
  }

  static std::string show(const json& value) { return briefJson(value); }

  void keys(const json& object, const std::string& key, const std::set<std::string>& allowed) const {
    if (!object.is_object()) fail(key, "expected an object, got " + show(object));
    for (const auto& [name, value] : object.items())
      if (!allowed.count(name)) {
        std::string known;
        for (const auto& a : allowed) known += (known.empty() ? "" : ", ") + a;
        fail(key.empty() ? name : key + "." + name, "unknown key (allowed: " + known + ")");
      }
  }

  std::string text(const json& value, const std::string& key) const {
    if (!value.is_string()) fail(key, "expected a string, got " + show(value));
    return value.get<std::string>();
  }

  int integer(const json& value, const std::string& key, int lo, int hi) const {
    if (!value.is_number_integer() && !value.is_number_unsigned())
      fail(key, "expected an integer, got " + show(value));
    const auto v = value.get<std::int64_t>();
    if (v < lo || v > hi) fail(key, std::to_string(v) + " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
    return int(v);
  }

  std::optional<double> numberOrNull(const json& value, const std::string& key) const {
    if (value.is_null()) return std::nullopt;
    if (!value.is_number()) fail(key, "expected a number or null, got " + show(value));
    const double v = value.get<double>();
    if (!std::isfinite(v)) fail(key, "expected a finite number");
    return v;
  }

  // The keys a column, a row and the spec's "settings" share.
  SweepSettings settings(const json& object, const std::string& key, const SweepSpec& spec) const {
    SweepSettings s;
    auto sub = [&](const char* name) { return key.empty() ? std::string(name) : key + "." + name; };
    if (object.contains("scene")) {
      s.scene = text(object["scene"], sub("scene"));
      if (!spec.scenes.count(*s.scene)) fail(sub("scene"), "'" + *s.scene + "' is not in \"scenes\"");
    }
    if (object.contains("size")) s.size = size(object["size"], sub("size"));
    if (object.contains("shadow_map")) s.shadowMap = integer(object["shadow_map"], sub("shadow_map"), 1, 16384);
    if (object.contains("depth_format")) s.depthFormat = depthFormat(object["depth_format"], sub("depth_format"));
    if (object.contains("subdivide")) s.subdivide = integer(object["subdivide"], sub("subdivide"), 0, 6);
    if (object.contains("params")) {
      const json& params = object["params"];
      if (!params.is_object()) fail(sub("params"), "expected an object of \"technique.name\": value");
      for (const auto& [name, value] : params.items()) {
        const std::string where = sub("params") + "." + name;
        parameterName(name, where);
        s.params[name] = parameterValue(value, where);
      }
    }
    return s;
  }

  std::string size(const json& value, const std::string& key) const {
    const std::string t = text(value, key);
    int w = 0, h = 0;
    if (t.find('x') == std::string::npos || std::sscanf(t.c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1 ||
        std::to_string(w) + "x" + std::to_string(h) != t)
      fail(key, "expected WxH such as 1280x720, got " + show(value));
    return t;
  }

  std::string depthFormat(const json& value, const std::string& key) const {
    const std::string t = text(value, key);
    if (t != "16" && t != "24" && t != "32f") fail(key, "expected 16, 24 or 32f, got " + show(value));
    return t;
  }

  // "technique.name" of a known technique (the parameter itself is checked when planned).
  void parameterName(const std::string& name, const std::string& where) const {
    const auto dot = name.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
      fail(where, "expected a key \"technique.name\" (e.g. pcf.kernel)");
    technique(name.substr(0, dot), where);
  }

  // A parameter's value as --set takes it.
  std::string parameterValue(const json& value, const std::string& where) const {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_boolean() || value.is_number_integer() || value.is_number_unsigned()) return value.dump();
    if (value.is_number_float() && std::isfinite(value.get<double>())) return value.dump();
    fail(where, "expected a number, string or boolean, got " + show(value));
  }

  // Names that become part of output file names: checked here, not when the files are
  // written after every cell has rendered.
  void fileNamePart(const std::string& name, const std::string& key) const {
    if (name.empty() || name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-_") != std::string::npos)
      fail(key, "expected lower-case letters, digits, '-' or '_' (it names the table's files), got " + show(json(name)));
    if (name.size() > kMaxSweepNameLength)
      fail(key, std::to_string(name.size()) + " characters, more than the limit of " + std::to_string(kMaxSweepNameLength) +
                    " (it names the table's files)");
  }

  void technique(const std::string& id, const std::string& key) const {
    if (id == kGroundTruthId) return;
    try {
      findTechnique(id);
    } catch (const InputError& error) {
      fail(key, error.what());
    }
  }

 private:
  fs::path file_;
};

const std::set<std::string> kSettingKeys = {"scene", "size", "shadow_map", "depth_format", "subdivide", "params"};

std::set<std::string> with(std::set<std::string> keys, std::initializer_list<const char*> more) {
  for (const char* k : more) keys.insert(k);
  return keys;
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
std::map<std::string, fs::path> expandScenes(const json& scenes, const SpecReader& r, const fs::path& spec,
                                             std::vector<std::string>& order) {
  std::map<std::string, fs::path> out;
  const json list = scenes.is_array() ? scenes : json::array({scenes});
  if (list.empty()) r.fail("scenes", "expected scene files, folders or globs, got an empty list");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string key = scenes.is_array() ? "scenes[" + std::to_string(i) + "]" : "scenes";
    const std::string text = r.text(list[i], key);
    fs::path path = text;
    if (path.is_relative()) path = spec.parent_path() / path;
    std::vector<fs::path> files;
    if (isGlob(text)) {
      files = globScenes(path.string());
      if (files.empty()) r.fail(key, "'" + text + "' matches no scene file");
    } else if (fs::is_directory(path)) {
      files = folderScenes(path);
      if (files.empty()) r.fail(key, "the folder " + path.string() + " holds no scene file (an empty corpus?)");
    } else if (fs::is_regular_file(path)) {
      files = {path};
    } else {
      r.fail(key, "no such scene file or folder: " + path.string());
    }
    for (const auto& file : files) {
      const std::string id = sceneIdOf(file);
      if (id.empty()) r.fail(key, "cannot name a scene after " + file.string());
      const fs::path absolute = fs::absolute(file).lexically_normal();
      const auto [it, fresh] = out.emplace(id, absolute);
      if (!fresh && it->second != absolute)
        r.fail(key, "two scene files would both be called '" + id + "': " + it->second.string() + " and " + absolute.string());
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
SweepAreaLight areaLightOf(const json& settings, const SpecReader& r) {
  SweepAreaLight area;
  if (settings.contains("reference")) {
    const std::string name = r.text(settings["reference"], "settings.reference");
    const std::map<std::string, SweepReference> names = {{"by_output", SweepReference::ByOutput},
                                                          {"hard", SweepReference::Hard},
                                                          {"soft", SweepReference::Soft},
                                                          {"both", SweepReference::Both}};
    const auto it = names.find(name);
    if (it == names.end()) r.fail("settings.reference", "expected hard, soft, both or by_output, got " + SpecReader::show(settings["reference"]));
    area.reference = it->second;
  }
  // Without a soft reference these would change nothing: a spec that names them means one.
  const bool hard = area.reference == SweepReference::Hard;
  if (settings.contains("area_samples")) {
    if (hard) r.fail("settings.area_samples", "the spec's reference is hard: no area-light reference is rendered");
    area.samples = r.integer(settings["area_samples"], "settings.area_samples", 1, 4096);
  }
  if (settings.contains("light_radius")) {
    if (hard) r.fail("settings.light_radius", "the spec's reference is hard: no area-light reference is rendered");
    const auto radius = r.numberOrNull(settings["light_radius"], "settings.light_radius");
    if (!radius || !(*radius > 0) || *radius > 1e6)
      r.fail("settings.light_radius", "expected a number in (0, 1e6] (spot: world units; directional: degrees below 90)");
    area.lightRadius = *radius;
  }
  return area;
}

// What the reference cannot serve: a soft measure without an area-light reference, and a
// soft reference over frames (the sequences compare with the hard ground truth only).
void checkAreaLight(const SweepSpec& spec, const json& document, const SpecReader& r) {
  const SweepReference reference = spec.area.reference;
  const Metric* measured = spec.measure.metric;
  if (measured && measured->reference == MetricReference::Soft && reference == SweepReference::Hard)
    r.fail("measure", "\"" + spec.measure.name + "\" is measured against the area-light reference, which settings.reference "
                      "\"hard\" does not render");
  if (measured && measured->reference == MetricReference::Soft && document.contains("frames"))
    r.fail("measure", "\"" + spec.measure.name + "\" is measured against the area-light reference, which a spec over "
                      "\"frames\" does not render (sequences are compared with the hard ground truth)");
  if (document.contains("frames") && spec.area.refusesNoRadius())
    r.fail("settings.reference", std::string(sweepReferenceName(reference)) +
                                     ": not available with \"frames\" (sequences are compared with the hard ground truth)");
}

SweepMeasure measureOf(const json& value, const SpecReader& r) {
  const std::string name = r.text(value, "measure");
  std::string known;
  for (const Metric& m : metricTable())
    if (!needsBaseline(m)) known += (known.empty() ? "" : ", ") + std::string(m.name);
  const auto found = findSweepMeasure(name);
  if (!found || (found->metric && !found->overFrames() && needsBaseline(*found->metric)))
    r.fail("measure", "expected a metric of the metric table (" + known +
                          "), or over frames flicker, crawl, crawl_missed or METRIC.mean/.p95/.max, got " +
                          SpecReader::show(value) +
                          (name.rfind("x_sm", 0) == 0 ? " (a ratio to sm: the table adds ×SM columns itself)" : ""));
  return *found;
}

// "axes": the columns as the product scene × size × shadow_map × depth_format × subdivide
// (every scene of "scenes", in order; the other axes where given), each column labelled
// by its values.
std::vector<SweepColumn> axisColumns(const json& axes, const SpecReader& r, const std::vector<std::string>& sceneOrder) {
  r.keys(axes, "axes", {"size", "shadow_map", "depth_format", "subdivide", "comment"});
  std::vector<SweepColumn> columns;
  for (const auto& id : sceneOrder) {
    SweepColumn column{id, {}};
    column.set.scene = id;
    columns.push_back(column);
  }
  auto multiply = [&](const char* key, auto apply) {
    if (!axes.contains(key)) return;
    const json& values = axes[key];
    const std::string where = std::string("axes.") + key;
    if (!values.is_array() || values.empty()) r.fail(where, "expected a non-empty array of values");
    std::vector<SweepColumn> product;
    for (const auto& column : columns)
      for (std::size_t i = 0; i < values.size(); ++i) {
        SweepColumn next = column;
        const std::string label = apply(next.set, values[i], where + "[" + std::to_string(i) + "]");
        next.label += " · " + label;
        product.push_back(std::move(next));
        if (product.size() > kMaxSweepEntries)
          r.fail(where, "the axes make more than " + std::to_string(kMaxSweepEntries) + " columns");
      }
    columns = std::move(product);
  };
  multiply("size", [&](SweepSettings& set, const json& value, const std::string& key) {
    set.size = r.size(value, key);
    return *set.size;
  });
  multiply("shadow_map", [&](SweepSettings& set, const json& value, const std::string& key) {
    set.shadowMap = r.integer(value, key, 1, 16384);
    return std::to_string(*set.shadowMap) + "²";
  });
  multiply("depth_format", [&](SweepSettings& set, const json& value, const std::string& key) {
    set.depthFormat = r.depthFormat(value, key);
    return "depth " + *set.depthFormat;
  });
  multiply("subdivide", [&](SweepSettings& set, const json& value, const std::string& key) {
    set.subdivide = r.integer(value, key, 0, 6);
    return "subdivide " + std::to_string(*set.subdivide);
  });
  return columns;
}

// A row with "vary": one row per combination of the values (keys in name order), each
// labelled "<label> name=value ...".
std::vector<SweepRow> varied(const SweepRow& row, const json& vary, const SpecReader& r, const std::string& key) {
  if (!vary.is_object() || vary.empty()) r.fail(key, "expected an object of \"technique.name\": [values]");
  std::vector<SweepRow> rows = {row};
  for (const auto& [name, values] : vary.items()) {
    const std::string where = key + "." + name;
    r.parameterName(name, where);
    if (!values.is_array() || values.empty()) r.fail(where, "expected a non-empty array of values");
    std::vector<SweepRow> product;
    for (const auto& base : rows)
      for (std::size_t i = 0; i < values.size(); ++i) {
        SweepRow next = base;
        const std::string text = r.parameterValue(values[i], where + "[" + std::to_string(i) + "]");
        next.set.params[name] = text;
        next.label.append(" ").append(name, name.find('.') + 1).append("=").append(text);
        product.push_back(std::move(next));
        if (product.size() > kMaxSweepRows) r.fail(where, "more than " + std::to_string(kMaxSweepRows) + " rows");
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

SweepSpec parseSweepSpec(const json& document, const fs::path& file, bool sceneFilesMustExist) {
  const SpecReader r(file);
  SweepSpec spec;
  spec.file = file;
  spec.document = document;
  r.keys(document, "", {"name", "title", "citation", "comment", "note", "scenes", "scene_order", "settings", "measure",
                        "frames", "columns", "axes", "rows", "techniques", "figure", "differences"});
  for (const char* required : {"name", "scenes"})
    if (!document.contains(required)) r.fail(required, "missing (required)");
  if (document.contains("columns") == document.contains("axes"))
    r.fail(document.contains("columns") ? "axes" : "columns",
           document.contains("columns") ? "give \"columns\" or \"axes\", not both" : "missing (required, or \"axes\")");
  if (!document.contains("rows") && !document.contains("techniques"))
    r.fail("rows", "missing (required, or \"techniques\")");
  spec.name = r.text(document["name"], "name");
  r.fileNamePart(spec.name, "name");
  if (spec.name == "records" || spec.name == "sweep" || spec.name == "spec") r.fail("name", "\"" + spec.name + "\" is the name of a sweep output file");
  if (document.contains("citation")) spec.citation = r.text(document["citation"], "citation");
  if (document.contains("title")) spec.title = r.text(document["title"], "title");
  if (document.contains("note")) spec.note = r.text(document["note"], "note");
  if (document.contains("comment")) r.text(document["comment"], "comment");
  if (document.contains("differences")) {
    if (!document["differences"].is_boolean()) r.fail("differences", "expected true or false");
    spec.differences = document["differences"].get<bool>();
  }

  const json& scenes = document["scenes"];
  std::vector<std::string> sceneOrder;  // the scene axis's order
  if (scenes.is_string() || scenes.is_array()) {
    spec.scenes = expandScenes(scenes, r, file, sceneOrder);
    // The expanded list is what the shards' identity covers: a scene added to the corpus
    // folder between two shards' runs makes them two specs, which merge refuses.
    spec.document["scenes"] = json::object();
    for (const auto& [id, path] : spec.scenes) spec.document["scenes"][id] = path.string();
    spec.document["scene_order"] = sceneOrder;
  } else if (!scenes.is_object() || scenes.empty()) {
    r.fail("scenes", "expected an object of id: scene file, a corpus folder, a glob or a list of them, not empty");
  }
  if (scenes.is_object() && document.contains("scene_order")) {  // an expanded spec.json, as a shard wrote it
    const json& order = document["scene_order"];
    if (!order.is_array() || order.size() != scenes.size()) r.fail("scene_order", "expected one id per scene");
    for (std::size_t i = 0; i < order.size(); ++i) {
      sceneOrder.push_back(r.text(order[i], "scene_order[" + std::to_string(i) + "]"));
      if (!scenes.contains(sceneOrder.back())) r.fail("scene_order[" + std::to_string(i) + "]", "not in \"scenes\"");
    }
  }
  if (scenes.is_object()) for (const auto& [id, path] : scenes.items()) {
    if (!document.contains("scene_order")) sceneOrder.push_back(id);
    r.fileNamePart(id, "scenes." + id);  // it names the close-up figure's file
    fs::path scene = r.text(path, "scenes." + id);
    if (scene.is_relative()) scene = file.parent_path() / scene;
    if (sceneFilesMustExist && !fs::is_regular_file(scene)) r.fail("scenes." + id, "no such scene file: " + scene.string());
    spec.scenes[id] = fs::absolute(scene).lexically_normal();
  }

  if (document.contains("settings")) {
    const json& settings = document["settings"];
    r.keys(settings, "settings", with(kSettingKeys, {"repeat", "reference", "area_samples", "light_radius"}));
    spec.settings = r.settings(settings, "settings", spec);
    if (settings.contains("repeat")) spec.repeat = r.integer(settings["repeat"], "settings.repeat", 1, 10000);
    spec.area = areaLightOf(settings, r);
  }
  if (document.contains("measure")) spec.measure = measureOf(document["measure"], r);
  checkAreaLight(spec, document, r);
  if (document.contains("frames")) {
    spec.frames = r.text(document["frames"], "frames");
    Scene probe;  // the syntax now; the range against each scene's frames when the sweep loads it
    auto frames = std::make_shared<Animation>();
    frames->frames = std::numeric_limits<int>::max();
    probe.animation = frames;
    try {
      parseFrameRange(*spec.frames, probe);
    } catch (const InputError& error) {
      const std::string what = error.what();
      r.fail("frames", what.find("outside") != std::string::npos ? *spec.frames + ": expected 0 <= A <= B"
                                                                 : what.substr(std::string("--frames: ").size()));
    }
  }
  if (spec.measure.overFrames() && !spec.frames)
    r.fail("measure", "\"" + spec.measure.name + "\" is a figure over frames: the spec needs \"frames\" (all or A:B[:STEP])");

  if (document.contains("axes")) spec.columns = axisColumns(document["axes"], r, sceneOrder);
  const json& columns = document.contains("columns") ? document["columns"] : json::array({nullptr});
  if (!columns.is_array() || columns.empty()) r.fail("columns", "expected a non-empty array");
  if (columns.size() > kMaxSweepColumns)
    r.fail("columns", std::to_string(columns.size()) + " columns, more than the limit of " + std::to_string(kMaxSweepColumns));
  for (std::size_t i = 0; document.contains("columns") && i < columns.size(); ++i) {
    const std::string key = "columns[" + std::to_string(i) + "]";
    r.keys(columns[i], key, with(kSettingKeys, {"label", "comment"}));
    if (!columns[i].contains("label")) r.fail(key + ".label", "missing (required)");
    spec.columns.push_back({r.text(columns[i]["label"], key + ".label"), r.settings(columns[i], key, spec)});
  }

  // "techniques": ["sm", "pcf"] is rows [{"techniques": ["sm"]}, {"techniques": ["pcf"]}].
  json rows = document.contains("rows") ? document["rows"] : json::array();
  if (!rows.is_array() || (document.contains("rows") && rows.empty())) r.fail("rows", "expected a non-empty array");
  if (document.contains("techniques")) {
    const json& techniques = document["techniques"];
    if (!techniques.is_array() || techniques.empty()) r.fail("techniques", "expected a non-empty array of ids");
    for (std::size_t t = 0; t < techniques.size(); ++t) {
      r.technique(r.text(techniques[t], "techniques[" + std::to_string(t) + "]"), "techniques[" + std::to_string(t) + "]");
      rows.push_back({{"techniques", json::array({techniques[t]})}});
    }
  }
  if (rows.size() > kMaxSweepRows)
    r.fail("rows", std::to_string(rows.size()) + " rows, more than the limit of " + std::to_string(kMaxSweepRows));
  std::size_t entries = 0;  // cells the table asks for, before equal ones are merged
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string key = "rows[" + std::to_string(i) + "]";
    const json& row = rows[i];
    r.keys(row, key, with(kSettingKeys, {"label", "group", "techniques", "vary", "passes", "not_measured",
                                         "not_measured_columns", "paper", "comment"}));
    if (!row.contains("techniques")) r.fail(key + ".techniques", "missing (required)");
    SweepRow parsed;
    if (row.contains("group")) parsed.group = r.text(row["group"], key + ".group");
    if (row.contains("comment")) r.text(row["comment"], key + ".comment");
    const json& techniques = row["techniques"];
    if (!techniques.is_array() || techniques.empty()) r.fail(key + ".techniques", "expected a non-empty array of ids");
    entries += techniques.size() * spec.columns.size();
    if (entries > kMaxSweepEntries)
      r.fail(key + ".techniques", "the table reaches " + std::to_string(entries) + " cells here, more than the limit of " +
                                      std::to_string(kMaxSweepEntries));
    for (std::size_t t = 0; t < techniques.size(); ++t) {
      const std::string where = key + ".techniques[" + std::to_string(t) + "]";
      parsed.techniques.push_back(r.text(techniques[t], where));
      r.technique(parsed.techniques.back(), where);
    }
    // Without a label a row is called after its techniques.
    if (row.contains("label")) parsed.label = r.text(row["label"], key + ".label");
    else
      for (const auto& t : parsed.techniques) parsed.label += (parsed.label.empty() ? "" : " + ") + t;
    parsed.set = r.settings(row, key, spec);
    if (row.contains("passes")) {
      const json& passes = row["passes"];
      if (!passes.is_array() || passes.empty()) r.fail(key + ".passes", "expected a non-empty array of pass names");
      parsed.passes.emplace();
      for (std::size_t p = 0; p < passes.size(); ++p) {
        const std::string where = key + ".passes[" + std::to_string(p) + "]";
        parsed.passes->push_back(r.text(passes[p], where));
        // The entry is the sum of the passes: one named twice would count twice.
        if (std::count(parsed.passes->begin(), parsed.passes->end(), parsed.passes->back()) > 1)
          r.fail(where, "\"" + parsed.passes->back() + "\" is already in the list");
      }
      // "frame" holds the G-buffer and every pass of the technique: any of them beside it
      // would count twice.
      const auto& names = *parsed.passes;
      if (std::count(names.begin(), names.end(), "frame") == 1 &&
          names.size() > std::size_t(1 + std::count(names.begin(), names.end(), "shading")))
        r.fail(key + ".passes", "\"frame\" is the whole frame already; only \"shading\" may join it");
    }
    if (row.contains("not_measured")) parsed.notMeasured = r.text(row["not_measured"], key + ".not_measured");
    if (row.contains("not_measured_columns")) {
      const json& columns = row["not_measured_columns"];
      if (parsed.notMeasured.empty()) r.fail(key + ".not_measured_columns", "needs \"not_measured\" (the reason)");
      if (!columns.is_array() || columns.empty()) r.fail(key + ".not_measured_columns", "expected a non-empty array of column indices");
      for (std::size_t k = 0; k < columns.size(); ++k)
        parsed.notMeasuredColumns.push_back(std::size_t(r.integer(
            columns[k], key + ".not_measured_columns[" + std::to_string(k) + "]", 0, int(spec.columns.size()) - 1)));
    }
    // A study of one's own has no paper's figures: a row without "paper" has none.
    json paper = row.contains("paper") ? row["paper"] : json::array();
    if (!row.contains("paper")) paper.get_ref<json::array_t&>().resize(spec.columns.size());
    if (!paper.is_array() || paper.size() != spec.columns.size())
      r.fail(key + ".paper", "expected an array of " + std::to_string(spec.columns.size()) +
                                 " numbers or nulls (one per column), got " + SpecReader::show(paper));
    for (std::size_t c = 0; c < paper.size(); ++c)
      parsed.paper.push_back(r.numberOrNull(paper[c], key + ".paper[" + std::to_string(c) + "]"));
    if (row.contains("vary")) {
      if (row.contains("paper")) r.fail(key + ".vary", "a row with \"paper\" figures cannot vary (whose figures would they be?)");
      for (auto& one : varied(parsed, row["vary"], r, key + ".vary")) spec.rows.push_back(std::move(one));
      if (spec.rows.size() > kMaxSweepRows) r.fail(key + ".vary", "more than " + std::to_string(kMaxSweepRows) + " rows");
      entries = 0;
      for (const auto& made : spec.rows) entries += made.techniques.size() * spec.columns.size();
      if (entries > kMaxSweepEntries)
        r.fail(key + ".vary", "the table reaches " + std::to_string(entries) + " cells here, more than the limit of " +
                                  std::to_string(kMaxSweepEntries));
    } else {
      spec.rows.push_back(std::move(parsed));
    }
  }

  if (document.contains("figure")) {
    const json& figure = document["figure"];
    r.keys(figure, "figure", {"column", "window", "comment"});
    if (figure.contains("column"))
      spec.figure.column = std::size_t(r.integer(figure["column"], "figure.column", 0, int(spec.columns.size()) - 1));
    if (figure.contains("window")) {
      const json& w = figure["window"];
      if (!w.is_array() || w.size() != 3) r.fail("figure.window", "expected [x, y, side] in pixels");
      spec.figure.window = std::array<int, 3>{r.integer(w[0], "figure.window[0]", 0, 8192),
                                              r.integer(w[1], "figure.window[1]", 0, 8192),
                                              r.integer(w[2], "figure.window[2]", 4, 8192)};
    }
  }
  return spec;
}

bool isHarnessPass(const std::string& pass) {
  return std::find(kHarnessPasses.begin(), kHarnessPasses.end(), pass) != kHarnessPasses.end();
}

}  // namespace testbed
