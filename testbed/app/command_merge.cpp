// `testbed merge --out DIR SHARD_DIR...`: joins the shards of one sweep into the tables a
// single run writes (docs/paper-runs.md "Paper runs"). Shards are files from elsewhere, so everything
// is verified before it is used (docs/input-limits.md): each file read by the strict
// capped reader; the spec fingerprint recomputed from the shard's own spec.json and
// overrides; shards of another spec, other overrides or another build, a shard given
// twice or missing refused; each record matched against its cell; figure images decoded
// only at their cell's size and channels; --out never an input; records made on
// different paths (docs/paths.md: different passes and memory) or by different shader
// compilers (docs/portability.md) refused. Records of different backends are kept in
// tables of their own.
#include <iostream>
#include <optional>
#include <set>

#include "groundtruth/shadow_volumes.h"
#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/app/sweep_report.h"
#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/io/json_reader.h"
#include "testbed/sweep/sweep_records.h"
#include "testbed/technique/path.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A shard's sweep.json is a few hundred bytes; spec.json is a spec (sweep_spec.h's cap).
constexpr std::uint64_t kMaxManifestBytes = 1ull << 20;

json readShardFile(const fs::path& dir, const char* name, std::uint64_t maxBytes) {
  const fs::path file = dir / name;
  std::error_code error;
  if (!fs::exists(fs::symlink_status(file, error)))
    throw InputError(file.string() + ": missing (not a sweep shard folder?)");
  return readJsonInput(file, maxBytes);
}

// True when `inner` is `outer` or lies inside it (both made absolute, links resolved as
// far as they exist).
bool within(const fs::path& inner, const fs::path& outer) {
  auto resolved = [](const fs::path& p) {
    std::string text = fs::weakly_canonical(fs::absolute(p)).lexically_normal().string();
    while (text.size() > 1 && text.back() == '/') text.pop_back();
    return text;
  };
  const std::string a = resolved(inner), b = resolved(outer);
  return a == b || b == "/" || a.rfind(b + "/", 0) == 0;
}

struct ShardDir {
  fs::path dir;
  json manifest, records, spec;
  Shard shard;
};

std::string pathText(const std::optional<TechniquePath>& path) {
  return path ? "the " + std::string(pathName(*path)) + " path" : "no recorded path";
}

// The shard's manifest (sweep.json) through the checked JSON reader.
JsonField manifestOf(const ShardDir& s) { return JsonField(s.manifest, (s.dir / "sweep.json").string()); }

std::string field(const ShardDir& s, const char* name) { return manifestOf(s)[name].text(); }

}  // namespace

CommandRunner addMergeCommand(CLI::App& app) {
  struct Options {
    std::string out;
    std::vector<std::string> shards, plugins;
    bool noPlot = false;
  };
  auto options = std::make_shared<Options>();
  auto* command = app.add_subcommand("merge", "join the shards of one sweep into its tables");
  addOutOption(*command, options->out);
  command->add_option("shards", options->shards, "the shards' --out folders")->required();
  addNoPlotFlag(*command, options->noPlot);
  addPluginOption(*command, options->plugins);

  return {command, [options, command]() {
    if (fs::exists(options->out) && !fs::is_directory(options->out))
      throw InputError("--out: " + options->out + " exists and is not a folder");
    for (const auto& dir : options->shards)
      if (within(options->out, dir))
        throw InputError("--out " + options->out + ": is the shard " + dir + " or inside it; merge never writes over its inputs");
    loadPlugins(options->plugins);
    std::vector<ShardDir> shards;
    for (const auto& dir : options->shards) {
      ShardDir s{dir, readShardFile(dir, "sweep.json", kMaxManifestBytes), readShardFile(dir, "records.json", kMaxJsonInputBytes),
                 readShardFile(dir, "spec.json", kMaxSweepSpecBytes), {}};
      const std::string manifest = (s.dir / "sweep.json").string();
      const JsonField shard = manifestOf(s).object()["shard"];
      try {
        s.shard = parseShard(shard.text());
      } catch (const InputError& error) {
        shard.fail(error.what());
      }
      overridesFromJson(manifestOf(s)["overrides"].json(), manifest + ": overrides");
      // The fingerprint is recomputed, not trusted: an edited spec.json is another spec.
      if (specFingerprint(s.spec, s.manifest["overrides"]) != field(s, "spec_fingerprint"))
        throw InputError((s.dir / "spec.json").string() +
                         ": does not match the shard's spec_fingerprint (edited after the run, or from another shard)");
      if (!s.records.is_array()) throw InputError((s.dir / "records.json").string() + ": expected an array of records");
      shards.push_back(std::move(s));
    }
    const ShardDir& first = shards.front();
    std::set<int> seen;
    for (const auto& s : shards) {
      const std::string where = (s.dir / "sweep.json").string();
      if (field(s, "spec_fingerprint") != field(first, "spec_fingerprint"))
        throw InputError(where + ": spec_fingerprint: another spec or other overrides than " + first.dir.string() +
                         " (" + field(s, "spec") + " vs " + field(first, "spec") + ")");
      if (field(s, "build") != field(first, "build"))
        throw InputError(where + ": build: made by another testbed build than " + first.dir.string());
      if (s.shard.count != first.shard.count)
        throw InputError(where + ": shard: " + s.shard.text() + " is not one of " + std::to_string(first.shard.count) +
                         " like " + first.dir.string());
      if (!seen.insert(s.shard.index).second) throw InputError(where + ": shard: " + s.shard.text() + " given twice");
    }
    for (int k = 1; k <= first.shard.count; ++k)
      if (!seen.count(k))
        throw InputError("merge: shard " + std::to_string(k) + "/" + std::to_string(first.shard.count) + " is missing");

    const SweepSpec spec = parseSweepSpec(first.spec, field(first, "spec_file"), false);
    const SweepPlan plan =
        planSweep(spec, overridesFromJson(first.manifest["overrides"], (first.dir / "sweep.json").string() + ": overrides"));
    std::vector<Record> records;
    std::map<std::size_t, const ShardDir*> ownerOf;
    std::string firstWhere;  // the first record, whose paths every other must share
    std::optional<TechniquePath> firstPath;
    ShaderPath firstShaderPath = ShaderPath::Glsl;
    for (const auto& s : shards)
      for (std::size_t i = 0; i < s.records.size(); ++i) {
        const std::string where = (s.dir / "records.json").string() + ": [" + std::to_string(i) + "]";
        Record record = readRecord(s.records[i], where);
        if (firstWhere.empty()) {
          firstWhere = where;
          firstPath = record.path;
          firstShaderPath = compiledBy(record);
        } else if (record.path != firstPath) {
          throw InputError(where + ".path: made on " + pathText(record.path) + ", " + firstWhere + " on " +
                           pathText(firstPath) + "; one table's shards run on one path (--path)");
        } else if (compiledBy(record) != firstShaderPath) {
          throw InputError(where + ".shader_path: compiled by " + std::string(shaderPathName(compiledBy(record))) + ", " +
                           firstWhere + " by " + std::string(shaderPathName(firstShaderPath)) +
                           "; one table's shards use one shader compiler (TESTBED_SHADER_PATH)");
        }
        if (!record.cell || *record.cell >= plan.cells.size())
          throw InputError(where + ".cell: missing or not a cell of the spec's " + std::to_string(plan.cells.size()));
        const std::size_t cell = *record.cell;
        if (!s.shard.owns(cell) || !ownerOf.emplace(cell, &s).second)
          throw InputError(where + ".cell: cell " + std::to_string(cell) + " does not belong to shard " + s.shard.text() +
                           " or is there twice");
        matchRecord(record, plan.cells[cell], where);
        records.push_back(std::move(record));
      }
    for (std::size_t cell = 0; cell < plan.cells.size(); ++cell)
      if (!ownerOf.count(cell))
        throw InputError("merge: cell " + std::to_string(cell) + " (" + plan.cells[cell].technique + " on " +
                         plan.cells[cell].scene + ") has no record in shard " +
                         Shard{int(cell % std::size_t(first.shard.count)) + 1, first.shard.count}.text());
    std::sort(records.begin(), records.end(), [](const Record& a, const Record& b) { return *a.cell < *b.cell; });

    std::map<std::size_t, FigureImages> figureImages;
    for (std::size_t cell : figureCells(spec, plan)) {
      const fs::path dir = ownerOf.at(cell)->dir;
      const glm::ivec2 size = parseSize(plan.cells[cell].size);
      std::error_code error;
      if (fs::exists(fs::symlink_status(dir / figureFileName(cell, "exr"), error)))
        figureImages[cell] = {readImage(dir / figureFileName(cell, "exr"), {size.x, size.y, 1}),
                              readImage(dir / figureFileName(cell, "png"), {size.x, size.y, 3})};
    }
    std::string machines, backends;
    std::set<std::string> hosts, allBackends;
    for (const auto& s : shards) {
      if (hosts.insert(field(s, "host")).second) machines += (machines.empty() ? "" : "; ") + field(s, "host");
      allBackends.insert(field(s, "backend"));
    }
    for (const auto& b : allBackends) backends += (backends.empty() ? "" : "; ") + b;
    json manifest = first.manifest;
    manifest["shard"] = "1/1";
    const std::string line = commandLine(*command);
    manifest["command"] = line;
    manifest["host"] = machines;
    manifest["backend"] = backends;
    manifest["merged_from"] = json::array();
    for (const auto& s : shards) manifest["merged_from"].push_back({{"dir", s.dir.string()}, {"shard", s.shard.text()},
                                                                    {"command", field(s, "command")}, {"host", field(s, "host")}});
    OutputFiles files(options->out);
    files.writeText("records.json", sweepRecordsJson(records, spec, plan).dump(2) + "\n");
    files.writeText("sweep.json", manifest.dump(2) + "\n");
    files.writeText("spec.json", first.spec.dump(2) + "\n");
    stageSweepReport(files, spec, plan, records,
                     {{"command", line}, {"machine", machines}, {"backend", backends}, {"build", field(first, "build")}},
                     figureImages, !options->noPlot);
    files.commit();
    std::cerr << "testbed: merged " << shards.size() << " shards, " << records.size() << " records, into " << options->out << "\n";
    return 0;
  }};
}

}  // namespace testbed
