// `testbed merge --out DIR SHARD_DIR...`: joins the shards of one sweep into the tables a
// single run writes (docs/paper-runs.md "Paper runs"). Refuses shards of another spec, other
// overrides or another build, a shard given twice or missing, and a cell without its
// record; records of different backends are kept in tables of their own.
#include <fstream>
#include <iostream>
#include <set>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/app/sweep_report.h"
#include "testbed/core/error.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json readJson(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string() + ": missing (not a sweep shard folder?)");
  try {
    return json::parse(in);
  } catch (const json::parse_error& error) {
    throw InputError(file.string() + ": not valid JSON (" + std::string(error.what()) + ")");
  }
}

struct ShardDir {
  fs::path dir;
  json manifest, records, spec;
  Shard shard;
};

std::string field(const ShardDir& s, const char* name) {
  if (!s.manifest.contains(name) || !s.manifest[name].is_string())
    throw InputError((s.dir / "sweep.json").string() + ": " + name + ": missing or not a string");
  return s.manifest[name].get<std::string>();
}

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

  return {command, [options]() {
    if (fs::exists(options->out) && !fs::is_directory(options->out))
      throw InputError("--out: " + options->out + " exists and is not a folder");
    loadPlugins(options->plugins);
    std::vector<ShardDir> shards;
    for (const auto& dir : options->shards) {
      ShardDir s{dir, readJson(fs::path(dir) / "sweep.json"), readJson(fs::path(dir) / "records.json"),
                 readJson(fs::path(dir) / "spec.json"), {}};
      try {
        s.shard = parseShard(field(s, "shard"));
      } catch (const InputError& error) {
        throw InputError((s.dir / "sweep.json").string() + ": shard: " + error.what());
      }
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
    const SweepPlan plan = planSweep(spec, overridesFromJson(first.manifest.at("overrides")));
    std::vector<Record> records;
    std::map<std::size_t, const ShardDir*> ownerOf;
    for (const auto& s : shards)
      for (std::size_t i = 0; i < s.records.size(); ++i) {
        const std::string where = (s.dir / "records.json").string() + ": [" + std::to_string(i) + "]";
        Record record = readRecord(s.records[i], where);
        if (!record.cell || *record.cell >= plan.cells.size())
          throw InputError(where + ".cell: missing or not a cell of the spec's " + std::to_string(plan.cells.size()));
        const std::size_t cell = *record.cell;
        if (!s.shard.owns(cell) || !ownerOf.emplace(cell, &s).second)
          throw InputError(where + ".cell: cell " + std::to_string(cell) + " does not belong to shard " + s.shard.text() +
                           " or is there twice");
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
      if (fs::exists(dir / figureFileName(cell, "exr")))
        figureImages[cell] = {readImage(dir / figureFileName(cell, "exr")), readImage(dir / figureFileName(cell, "png"))};
    }
    std::string commandLine = "testbed merge --out " + options->out, machines, backends;
    std::set<std::string> hosts, allBackends;
    for (const auto& s : shards) {
      commandLine += " " + s.dir.string();
      if (hosts.insert(field(s, "host")).second) machines += (machines.empty() ? "" : "; ") + field(s, "host");
      allBackends.insert(field(s, "backend"));
    }
    for (const auto& b : allBackends) backends += (backends.empty() ? "" : "; ") + b;
    json manifest = first.manifest;
    manifest["shard"] = "1/1";
    manifest["command"] = commandLine;
    manifest["host"] = machines;
    manifest["backend"] = backends;
    manifest["merged_from"] = json::array();
    for (const auto& s : shards) manifest["merged_from"].push_back({{"dir", s.dir.string()}, {"shard", s.shard.text()},
                                                                    {"command", field(s, "command")}, {"host", field(s, "host")}});
    OutputFiles files(options->out);
    files.writeText("records.json", json(records).dump(2) + "\n");
    files.writeText("sweep.json", manifest.dump(2) + "\n");
    files.writeText("spec.json", first.spec.dump(2) + "\n");
    stageSweepReport(files, spec, plan, records,
                     {{"command", commandLine}, {"machine", machines}, {"backend", backends}, {"build", field(first, "build")}},
                     figureImages);
    files.commit();
    if (!options->noPlot) plotSweepTables(options->out, spec.name);
    std::cerr << "testbed: merged " << shards.size() << " shards, " << records.size() << " records, into " << options->out << "\n";
    return 0;
  }};
}

}  // namespace testbed
