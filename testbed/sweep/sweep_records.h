#pragma once
// A sweep's records as files: each record written with the row and column labels of the
// table entries that read it, each checked against its cell before it is used (merge
// reads shards, a resumed run reads what an interrupted one left), and the resume folder
// that lets a re-submitted sweep or shard skip the cells it already finished
// (docs/paper-runs.md "Resuming").
#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/harness/record.h"
#include "testbed/io/image_io.h"
#include "testbed/sweep/sweep_plan.h"
#include "testbed/sweep/sweep_spec.h"

namespace testbed {

// Throws InputError "<where>.<field>: ..." when `record` is not what `cell` asks for: its
// technique, output and map size, depth format and parameters resolved as the sweep
// resolves them.
void matchRecord(const Record& record, const SweepCell& cell, const std::string& where);

// The record as records.json holds it: the record, its "cell", and the "row" and "column"
// labels of the first table entry that reads it ("entries": all of them, [row, column]);
// a ground truth that only serves as the reference has the row "groundtruth" and the
// column of the first entry it serves.
nlohmann::json sweepRecordJson(const Record& record, const SweepSpec& spec, const SweepPlan& plan);
nlohmann::json sweepRecordsJson(const std::vector<Record>& records, const SweepSpec& spec, const SweepPlan& plan);

// What a finished cell must share with the run that would reuse it.
struct SweepIdentity {
  std::string specFingerprint, build, backend;
};

struct CellImages {
  ImageF visibility;  // one channel, NaN background
  ImageF shaded;      // RGB, for people
};

struct ResumedCell {
  Record record;
  std::optional<CellImages> images;  // figure cells only
};

// The folder inside --out where each finished cell is written at once, so that a killed
// run leaves them behind; removed when the run commits its outputs.
inline constexpr const char* kResumeFolder = ".testbed-resume";

// Writes the cell's record (and, for a figure cell, its images) into OUT/.testbed-resume,
// each file complete or absent (written under another name, then renamed).
void saveFinishedCell(const std::filesystem::path& out, const SweepIdentity& identity, const Record& record,
                      const CellImages* images);

// The cells of `shard` that need not run again: records found in OUT/.testbed-resume and
// in OUT/records.json (a finished run of the same spec, build and shard), each verified:
// read strictly, of this spec, build and backend, a cell of the shard, matching its cell,
// with its error block; a figure cell also needs its images. Whatever fails is reported
// on `log`, one line naming the file and why, and runs again.
std::map<std::size_t, ResumedCell> loadFinishedCells(const std::filesystem::path& out, const SweepIdentity& identity,
                                                     const SweepPlan& plan, const Shard& shard,
                                                     const std::vector<std::size_t>& figureCells, std::ostream& log);

// Removes the resume folder's files (and the folder, when empty) after a commit.
void removeFinishedCells(const std::filesystem::path& out);

}  // namespace testbed
