#include "testbed/sweep/sweep_records.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>

#include "groundtruth/shadow_volumes.h"
#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/io/json_reader.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A sweep's sweep.json is a few hundred bytes.
constexpr std::uint64_t kMaxManifestBytes = 1ull << 20;

// A cell's "WxH", valid since the spec was read.
std::pair<int, int> pixelsOf(const SweepCell& cell) {
  int w = 0, h = 0;
  std::sscanf(cell.size.c_str(), "%dx%d", &w, &h);
  return {w, h};
}

std::string cellFile(std::size_t cell, const char* extension) {
  return "cell-" + std::to_string(cell) + "." + extension;
}

// Written beside its final name, then renamed: a reader sees the whole file or none.
template <typename Write>
void writeWhole(const fs::path& file, Write write) {
  const fs::path partial = file.parent_path() / (".partial-" + file.filename().string());
  write(partial);
  fs::rename(partial, file);
}

// The reason `record` cannot stand for `cell` in this run, or "" when it can.
std::string problemOf(const Record& record, std::size_t cell, const SweepPlan& plan, const Shard& shard,
                      const SweepIdentity& identity, const std::string& where) {
  if (!record.cell || *record.cell != cell) return "its cell is not " + std::to_string(cell);
  if (cell >= plan.cells.size() || !shard.owns(cell)) return "cell " + std::to_string(cell) + " is not one of shard " + shard.text();
  if (record.backend != identity.backend) return "made on " + record.backend + ", not " + identity.backend;
  if (!record.error) return "it has no error block";
  try {
    matchRecord(record, plan.cells[cell], where);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

std::optional<CellImages> imagesOf(const fs::path& exr, const fs::path& png, const SweepCell& cell) {
  const auto [w, h] = pixelsOf(cell);
  std::error_code error;
  if (!fs::is_regular_file(exr, error) || !fs::is_regular_file(png, error)) return std::nullopt;
  try {
    return CellImages{readImage(exr, {w, h, 1}), readImage(png, {w, h, 3})};
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace

void matchRecord(const Record& record, const SweepCell& cell, const std::string& where) {
  const RegisteredTechnique& technique =
      cell.technique == kGroundTruthId ? shadowVolumeGroundTruth() : findTechnique(cell.technique);
  const json params = resolveParameters(cell.technique, technique.info->parameters, cell.params).toJson();
  const auto [w, h] = pixelsOf(cell);
  auto differs = [&](const char* field, const std::string& got, const std::string& expected) {
    throw InputError(where + "." + field + ": " + got + ", but cell " + std::to_string(record.cell.value_or(0)) + " is " +
                     expected + " (a record edited or from another spec)");
  };
  if (record.technique != cell.technique) differs("technique", record.technique, cell.technique);
  if (record.width != w || record.height != h)
    differs("width", std::to_string(record.width) + "x" + std::to_string(record.height), cell.size);
  if (record.shadowMap != cell.shadowMap)
    differs("shadow_map", std::to_string(record.shadowMap), std::to_string(cell.shadowMap));
  if (record.depthFormat != cell.depthFormat) differs("depth_format", record.depthFormat, cell.depthFormat);
  if (record.params != params) differs("params", briefJson(record.params), briefJson(params));
  // Soft metrics where the spec judges the cell against the area-light reference, none
  // where it does not (a cell judged where its light has a radius may have either: the
  // scene decides, and merge does not read scenes).
  const bool soft = record.error && record.error->softRmse;
  if (soft && cell.soft == SoftJudging::None)
    differs("error.soft_rmse", "measured", "judged against the hard ground truth only");
  if (!soft && record.error && cell.soft == SoftJudging::Required)
    differs("error.soft_rmse", "null", "judged against the area-light reference too");
  if (soft && !record.areaReference)
    differs("area_reference", "missing", "judged against an area-light reference, which the record must name");
  if (record.sequence.has_value() != cell.frames.has_value())
    differs("sequence", record.sequence ? "a sequence" : "one frame",
            cell.frames ? "run over frames " + *cell.frames : "one frame");
}

namespace {

using Readers = std::vector<std::vector<std::pair<std::size_t, std::size_t>>>;

json labelled(const Record& record, const SweepSpec& spec, const SweepPlan& plan, const Readers& readers) {
  json out = record;
  if (!record.cell || *record.cell >= plan.cells.size()) return out;
  const std::size_t cell = *record.cell;
  auto entry = [&](std::size_t r, std::size_t c) { return json::array({spec.rows[r].label, spec.columns[c].label}); };
  json entries = json::array();
  for (const auto& [r, c] : readers[cell]) entries.push_back(entry(r, c));
  if (entries.empty())  // a reference only: the column of the first entry it serves
    for (std::size_t other = 0; other < plan.cells.size() && entries.empty(); ++other)
      if (plan.cells[other].truthCell == cell && !readers[other].empty())
        entries.push_back(json::array({kGroundTruthId, spec.columns[readers[other].front().second].label}));
  if (entries.empty()) return out;
  out["row"] = entries.front()[0];
  out["column"] = entries.front()[1];
  out["entries"] = entries;
  return out;
}

}  // namespace

json sweepRecordJson(const Record& record, const SweepSpec& spec, const SweepPlan& plan) {
  return labelled(record, spec, plan, plan.readers());
}

json sweepRecordsJson(const std::vector<Record>& records, const SweepSpec& spec, const SweepPlan& plan) {
  const Readers readers = plan.readers();
  json out = json::array();
  for (const auto& record : records) out.push_back(labelled(record, spec, plan, readers));
  return out;
}

void saveFinishedCell(const fs::path& out, const SweepIdentity& identity, const Record& record, const CellImages* images) {
  const fs::path dir = out / kResumeFolder;
  fs::create_directories(dir);
  const std::size_t cell = record.cell.value();
  if (images) {  // first, so that a record on disk always has its images
    // The partial name keeps the extension, which picks the format.
    writeWhole(dir / cellFile(cell, "exr"), [&](const fs::path& file) { writeImage(file, images->visibility); });
    writeWhole(dir / cellFile(cell, "png"), [&](const fs::path& file) { writeImage(file, images->shaded); });
  }
  const json entry = {{"spec_fingerprint", identity.specFingerprint}, {"build", identity.build}, {"record", record}};
  writeWhole(dir / cellFile(cell, "json"), [&](const fs::path& file) {
    std::ofstream stream(file, std::ios::binary | std::ios::trunc);
    stream << entry.dump() << "\n";
    stream.close();
    if (!stream) throw std::runtime_error(file.string() + ": cannot write");
  });
}

std::map<std::size_t, ResumedCell> loadFinishedCells(const fs::path& out, const SweepIdentity& identity,
                                                     const SweepPlan& plan, const Shard& shard,
                                                     const std::vector<std::size_t>& figureCells, std::ostream& log) {
  std::map<std::size_t, ResumedCell> found;
  const std::set<std::size_t> figure(figureCells.begin(), figureCells.end());
  auto consider = [&](const json& value, std::size_t cell, const std::string& where, const fs::path& exr,
                      const fs::path& png) {
    try {
      ResumedCell resumed{readRecord(value, where), std::nullopt};
      const std::string problem = problemOf(resumed.record, cell, plan, shard, identity, where);
      if (!problem.empty()) {
        log << "sweep: " << where << ": " << problem << "; running the cell again\n";
        return;
      }
      if (figure.count(cell)) {
        resumed.images = imagesOf(exr, png, plan.cells[cell]);
        if (!resumed.images) {
          log << "sweep: " << where << ": a figure cell without readable images; running the cell again\n";
          return;
        }
      }
      found.insert_or_assign(cell, std::move(resumed));
    } catch (const InputError& error) {
      log << "sweep: " << error.what() << "; running the cell again\n";
    }
  };
  std::error_code error;
  // A finished run of the same spec, build and shard: its records.json.
  if (fs::is_regular_file(out / "sweep.json", error) && fs::is_regular_file(out / "records.json", error)) {
    try {
      const json manifest = readJsonInput(out / "sweep.json", kMaxManifestBytes);
      if (manifest.is_object() && manifest.value("spec_fingerprint", "") == identity.specFingerprint &&
          manifest.value("build", "") == identity.build && manifest.value("shard", "") == shard.text()) {
        const json records = readJsonInput(out / "records.json");
        for (std::size_t i = 0; records.is_array() && i < records.size(); ++i) {
          const json& r = records[i];
          const std::string where = (out / "records.json").string() + ": [" + std::to_string(i) + "]";
          std::size_t cell = 0;
          try {
            cell = std::size_t(JsonField(r, "", where).object()["cell"].count());
          } catch (const InputError& e) {
            log << "sweep: " << e.what() << "; running the cell again\n";
            continue;
          }
          consider(r, cell, where, out / ("figure-cell-" + std::to_string(cell) + ".exr"),
                   out / ("figure-cell-" + std::to_string(cell) + ".png"));
        }
      }
    } catch (const InputError& e) {
      log << "sweep: " << e.what() << "; not resuming from it\n";
    }
  }
  // Cells an interrupted run finished.
  const fs::path dir = out / kResumeFolder;
  if (fs::is_directory(dir, error))
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind("cell-", 0) != 0 || entry.path().extension() != ".json") continue;
      std::size_t cell = 0;
      const std::string digits = name.substr(5, name.size() - 10);
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
      cell = std::stoul(digits);
      const std::string where = entry.path().string();
      if (!fs::is_regular_file(entry.symlink_status(error))) {  // a link is not followed out of the folder
        log << "sweep: " << where << ": not a regular file (a link or a folder); running the cell again\n";
        continue;
      }
      try {
        const json value = readJsonInput(entry.path());
        if (!value.is_object() || value.value("spec_fingerprint", "") != identity.specFingerprint ||
            value.value("build", "") != identity.build || !value.contains("record")) {
          log << "sweep: " << where << ": of another spec or build; running the cell again\n";
          continue;
        }
        consider(value["record"], cell, where + ": record", dir / cellFile(cell, "exr"), dir / cellFile(cell, "png"));
      } catch (const InputError& e) {
        log << "sweep: " << e.what() << "; running the cell again\n";
      }
    }
  return found;
}

void removeFinishedCells(const fs::path& out) {
  const fs::path dir = out / kResumeFolder;
  std::error_code error;
  if (!fs::is_directory(fs::symlink_status(dir, error))) return;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    const auto type = entry.symlink_status(error).type();
    const bool ours = type == fs::file_type::regular || type == fs::file_type::symlink;  // never a folder under the name
    if (ours && (name.rfind("cell-", 0) == 0 || name.rfind(".partial-cell-", 0) == 0)) fs::remove(entry.path(), error);
  }
  fs::remove(dir, error);  // only when empty
}

}  // namespace testbed
