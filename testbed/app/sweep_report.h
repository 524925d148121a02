#pragma once
// What `sweep` (one whole run) and `merge` (joined shards) write from the records: each
// backend's table as <name>.md and <name>.json, its plot (<name>.png, <name>.svg, by
// scripts/sweep_plot.py) and the close-up figure (<name>-closeup.png), plus the identity
// files that let shards be checked and joined (docs/paper-runs.md "Paper runs").
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/io/image_io.h"
#include "testbed/sweep/sweep_plan.h"
#include "testbed/sweep/sweep_records.h"
#include "testbed/sweep/sweep_table.h"

namespace testbed {

// The identity of the running binary (a fingerprint of its bytes): shards of other
// builds are refused by merge.
std::string buildFingerprint();
std::string hostDescription();  // host name and CPU model

// The fingerprint of a spec document with the command line's overrides.
std::string specFingerprint(const nlohmann::json& document, const nlohmann::json& overrides);
nlohmann::json overridesJson(const SweepOverrides& overrides);
// Reads a shard's "overrides" back, every field checked: throws InputError
// "<where>.<key>: <what>".
SweepOverrides overridesFromJson(const nlohmann::json& overrides, const std::string& where);

using FigureImages = CellImages;  // a figure cell's visibility and shaded frame

// Stages every backend's table (records of different backends never share a table) and
// the close-up figure of the figure column's cells into `files`. `plots`: the tables'
// plots too, drawn by scripts/sweep_plot.py; throws std::runtime_error when it fails, so
// the set is committed with all its plots or not at all.
void stageSweepReport(OutputFiles& files, const SweepSpec& spec, const SweepPlan& plan,
                      const std::vector<Record>& records, const SweepHeader& header,
                      const std::map<std::size_t, FigureImages>& figureImages, bool plots);

// The cells whose images the close-up figure shows: the figure column's, with their
// ground truth. Saved by the shard that runs them as figure-cell-<k>.exr / .png.
std::vector<std::size_t> figureCells(const SweepSpec& spec, const SweepPlan& plan);
std::string figureFileName(std::size_t cell, const char* extension);

}  // namespace testbed
