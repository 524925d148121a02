// Sweep specs are hand-written like scene files, so every mistake is one line naming the
// file and the key path ("paper/x.json: rows[2].paper[1]: expected a number or null").
#include "testbed/sweep/sweep_spec.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "testbed/core/error.h"
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

  // Text that lands in a cell of the markdown table: a '|' would split the cell and a line
  // break end the table, so both are refused here rather than the table coming out torn.
  std::string tableText(const json& value, const std::string& key) const {
    const std::string t = text(value, key);
    for (unsigned char c : t)
      if (c == '|' || c < 0x20 || c == 0x7f)
        fail(key, std::string(c == '|' ? "'|'" : "a control character (a line break?)") +
                      " would break the markdown table, got " + show(value));
    return t;
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
    if (object.contains("size")) {
      s.size = text(object["size"], sub("size"));
      const auto x = s.size->find('x');
      int w = 0, h = 0;
      if (x == std::string::npos || std::sscanf(s.size->c_str(), "%dx%d", &w, &h) != 2 || w < 1 || h < 1 ||
          std::to_string(w) + "x" + std::to_string(h) != *s.size)
        fail(sub("size"), "expected WxH such as 1280x720, got " + show(object["size"]));
    }
    if (object.contains("shadow_map")) s.shadowMap = integer(object["shadow_map"], sub("shadow_map"), 1, 16384);
    if (object.contains("depth_format")) {
      s.depthFormat = text(object["depth_format"], sub("depth_format"));
      if (*s.depthFormat != "16" && *s.depthFormat != "24" && *s.depthFormat != "32f")
        fail(sub("depth_format"), "expected 16, 24 or 32f, got " + show(object["depth_format"]));
    }
    if (object.contains("subdivide")) s.subdivide = integer(object["subdivide"], sub("subdivide"), 0, 6);
    if (object.contains("params")) {
      const json& params = object["params"];
      if (!params.is_object()) fail(sub("params"), "expected an object of \"technique.name\": value");
      for (const auto& [name, value] : params.items()) {
        const std::string where = sub("params") + "." + name;
        const auto dot = name.find('.');
        if (dot == std::string::npos || dot == 0 || dot + 1 == name.size())
          fail(where, "expected a key \"technique.name\" (e.g. pcf.kernel)");
        technique(name.substr(0, dot), where);
        if (value.is_string()) s.params[name] = value.get<std::string>();
        else if (value.is_boolean() || value.is_number_integer() || value.is_number_unsigned()) s.params[name] = value.dump();
        else if (value.is_number_float() && std::isfinite(value.get<double>())) s.params[name] = value.dump();
        else fail(where, "expected a number, string or boolean, got " + show(value));
      }
    }
    return s;
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

}  // namespace

bool SweepRow::measured(std::size_t column) const {
  if (notMeasured.empty()) return true;
  if (notMeasuredColumns.empty()) return false;
  return std::find(notMeasuredColumns.begin(), notMeasuredColumns.end(), column) == notMeasuredColumns.end();
}

SweepSpec loadSweepSpec(const fs::path& file) { return parseSweepSpec(readJsonInput(file, kMaxSweepSpecBytes), file); }

SweepSpec parseSweepSpec(const json& document, const fs::path& file, bool sceneFilesMustExist) {
  const SpecReader r(file);
  SweepSpec spec;
  spec.file = file;
  spec.document = document;
  r.keys(document, "", {"name", "title", "citation", "comment", "note", "scenes", "settings", "measure", "columns",
                        "rows", "figure"});
  for (const char* required : {"name", "citation", "scenes", "columns", "rows"})
    if (!document.contains(required)) r.fail(required, "missing (required)");
  spec.name = r.text(document["name"], "name");
  r.fileNamePart(spec.name, "name");
  if (spec.name == "records" || spec.name == "sweep" || spec.name == "spec") r.fail("name", "\"" + spec.name + "\" is the name of a sweep output file");
  spec.citation = r.text(document["citation"], "citation");
  if (document.contains("title")) spec.title = r.text(document["title"], "title");
  if (document.contains("note")) spec.note = r.text(document["note"], "note");
  if (document.contains("comment")) r.text(document["comment"], "comment");

  const json& scenes = document["scenes"];
  if (!scenes.is_object() || scenes.empty()) r.fail("scenes", "expected an object of id: scene file, not empty");
  for (const auto& [id, path] : scenes.items()) {
    r.fileNamePart(id, "scenes." + id);  // it names the close-up figure's file
    fs::path scene = r.text(path, "scenes." + id);
    if (scene.is_relative()) scene = file.parent_path() / scene;
    if (sceneFilesMustExist && !fs::is_regular_file(scene)) r.fail("scenes." + id, "no such scene file: " + scene.string());
    spec.scenes[id] = fs::absolute(scene).lexically_normal();
  }

  if (document.contains("settings")) {
    const json& settings = document["settings"];
    r.keys(settings, "settings", with(kSettingKeys, {"repeat"}));
    spec.settings = r.settings(settings, "settings", spec);
    if (settings.contains("repeat")) spec.repeat = r.integer(settings["repeat"], "settings.repeat", 1, 10000);
  }
  if (document.contains("measure")) {
    spec.measure = findMetric(r.text(document["measure"], "measure"), kSweepMeasure);
    if (!spec.measure) {
      std::string known;
      for (const Metric& m : metricTable())
        if (m.shownIn(kSweepMeasure)) known += (known.empty() ? "" : ", ") + std::string(m.name);
      const auto last = known.rfind(", ");
      if (last != std::string::npos) known.replace(last, 2, " or ");
      r.fail("measure", "expected " + known + ", got " + SpecReader::show(document["measure"]));
    }
  }

  const json& columns = document["columns"];
  if (!columns.is_array() || columns.empty()) r.fail("columns", "expected a non-empty array");
  if (columns.size() > kMaxSweepColumns)
    r.fail("columns", std::to_string(columns.size()) + " columns, more than the limit of " + std::to_string(kMaxSweepColumns));
  for (std::size_t i = 0; i < columns.size(); ++i) {
    const std::string key = "columns[" + std::to_string(i) + "]";
    r.keys(columns[i], key, with(kSettingKeys, {"label", "comment"}));
    if (!columns[i].contains("label")) r.fail(key + ".label", "missing (required)");
    spec.columns.push_back({r.tableText(columns[i]["label"], key + ".label"), r.settings(columns[i], key, spec)});
  }

  const json& rows = document["rows"];
  if (!rows.is_array() || rows.empty()) r.fail("rows", "expected a non-empty array");
  if (rows.size() > kMaxSweepRows)
    r.fail("rows", std::to_string(rows.size()) + " rows, more than the limit of " + std::to_string(kMaxSweepRows));
  std::size_t entries = 0;  // cells the table asks for, before equal ones are merged
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string key = "rows[" + std::to_string(i) + "]";
    const json& row = rows[i];
    r.keys(row, key, with(kSettingKeys, {"label", "group", "techniques", "passes", "not_measured", "not_measured_columns", "paper", "comment"}));
    for (const char* required : {"label", "techniques", "paper"})
      if (!row.contains(required)) r.fail(key + "." + required, "missing (required)");
    SweepRow parsed;
    parsed.label = r.tableText(row["label"], key + ".label");
    if (row.contains("group")) parsed.group = r.tableText(row["group"], key + ".group");
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
    }
    if (row.contains("not_measured")) parsed.notMeasured = r.tableText(row["not_measured"], key + ".not_measured");
    if (row.contains("not_measured_columns")) {
      const json& columns = row["not_measured_columns"];
      if (parsed.notMeasured.empty()) r.fail(key + ".not_measured_columns", "needs \"not_measured\" (the reason)");
      if (!columns.is_array() || columns.empty()) r.fail(key + ".not_measured_columns", "expected a non-empty array of column indices");
      for (std::size_t k = 0; k < columns.size(); ++k)
        parsed.notMeasuredColumns.push_back(std::size_t(r.integer(
            columns[k], key + ".not_measured_columns[" + std::to_string(k) + "]", 0, int(spec.columns.size()) - 1)));
    }
    const json& paper = row["paper"];
    if (!paper.is_array() || paper.size() != spec.columns.size())
      r.fail(key + ".paper", "expected an array of " + std::to_string(spec.columns.size()) +
                                 " numbers or nulls (one per column), got " + SpecReader::show(paper));
    for (std::size_t c = 0; c < paper.size(); ++c)
      parsed.paper.push_back(r.numberOrNull(paper[c], key + ".paper[" + std::to_string(c) + "]"));
    spec.rows.push_back(std::move(parsed));
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

}  // namespace testbed
