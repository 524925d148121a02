#pragma once
// A sweep spec (docs/paper-runs.md "Spec"): the scenes, the table's rows (techniques with
// parameters) and columns (shadow map, output size, scene, subdivision, any parameter),
// what is measured, and the paper's own figures beside each row, cited. Read from JSON
// and validated like scene files: any mistake is one InputError naming the file and key.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/harness/metric_table.h"

namespace testbed {

// Caps on a spec (docs/input-limits.md): the paper's tables are a few kilobytes and at
// most a few hundred cells; these leave room for any real table and refuse, before
// anything is planned or rendered, a spec that would run for months or exhaust memory.
inline constexpr std::uint64_t kMaxSweepSpecBytes = 1ull << 20;
inline constexpr std::size_t kMaxSweepColumns = 256;
inline constexpr std::size_t kMaxSweepRows = 1024;
inline constexpr std::size_t kMaxSweepEntries = 20000;  // rows × columns × techniques of a row
inline constexpr std::size_t kMaxSweepNameLength = 64;    // it names the table's files

// The reference that every table can time (the shadow volumes).
inline constexpr const char* kGroundTruthId = "groundtruth";

// Settings a column or row may change; unset fields fall back to the level above
// (column, then row, then the spec's "settings", then the command line's defaults).
struct SweepSettings {
  std::optional<std::string> scene;
  std::optional<std::string> size;  // "WxH"
  std::optional<int> shadowMap;
  std::optional<std::string> depthFormat;
  std::optional<int> subdivide;     // Loop subdivisions applied to every mesh of the scene
  std::map<std::string, std::string> params;  // "technique.name" → value text (as --set)
};

struct SweepColumn {
  std::string label;
  SweepSettings set;
};

// What a row's `passes` may name beside its technique's own passes: "gbuffer" (the G-buffer
// pass), "frame" (the whole frame, frame_ms's: G-buffer plus every pass of the technique)
// and "shading" (the harness's shading pass after the frame, harness/shading.h, in no
// frame: EDTSM* Table 4's totals add it as the paper's do).
inline constexpr std::array<const char*, 3> kHarnessPasses = {"gbuffer", "frame", "shading"};
bool isHarnessPass(const std::string& pass);

struct SweepRow {
  std::string group;                    // shown once per run of equal groups ("3 × 3")
  std::string label;                    // the paper's row name
  std::vector<std::string> techniques;  // several: the mean of their values (the papers' "pre-filtering")
  SweepSettings set;
  // Sum of these passes instead of the whole frame: the technique's own or kHarnessPasses.
  std::optional<std::vector<std::string>> passes;
  // Non-empty: entries we cannot measure (no such step here, a kernel beyond our range),
  // shown as "—" with this reason; all columns, or only those in notMeasuredColumns.
  std::string notMeasured;
  std::vector<std::size_t> notMeasuredColumns;
  std::vector<std::optional<double>> paper;   // one per column; null where the paper gives none

  bool measured(std::size_t column) const;
};

struct SweepFigure {
  std::size_t column = 0;  // the column whose cells are shown
  std::optional<std::array<int, 3>> window;  // x, y, side in pixels; unset: where techniques differ most
};

// What a table's numbers are: a metric of the metric table, read from the record; or, for
// a spec over frames, a figure of its sequence (docs/paper-runs.md "Frames"): `flicker`,
// `crawl`, `crawl_missed`, or a stored metric's mean, p95 or max over the frames
// ("rmse.p95").
struct SweepMeasure {
  std::string name;
  const Metric* metric = nullptr;  // the metric itself, or the one a series statistic summarizes; null for flicker and crawl
  std::string sequencePointer;     // non-empty: a JSON pointer into Record::sequence

  bool overFrames() const { return !sequencePointer.empty(); }
  std::optional<double> value(const Record& record) const;
  std::string unit() const;
  int digits() const;
  bool error() const;  // an error figure (its ratio to sm is an error ratio, not a cost)
  Better better() const;
};

// What a sweep's techniques are judged against (docs/paper-runs.md "Reference"): the hard
// ground truth (shadow volumes of the point light) always; the area-light reference too
// for every technique (Soft, Both: the same metrics, the hard ones being free) or only for
// those whose declared output is filtered (ByOutput, the default: a hard technique
// answers lit or shadowed, which the exact hard ground truth judges; a filtered one
// answers a fraction, which only a reference with a penumbra can judge).
enum class SweepReference { ByOutput, Hard, Soft, Both };
const char* sweepReferenceName(SweepReference reference);

// The area-light reference a spec asks for: `reference`, `area_samples` and `light_radius`
// of its "settings" (one set per spec: the reference is rendered once per scene, output
// size and frame and every cell of it reads it).
struct SweepAreaLight {
  SweepReference reference = SweepReference::ByOutput;
  int samples = 64;                    // point-light samples over the light's disk (1..4096)
  std::optional<double> lightRadius;   // replaces every scene's light.radius (spot: world units; directional: degrees)
  bool refusesNoRadius() const { return reference == SweepReference::Soft || reference == SweepReference::Both; }
};

// The measure called `name`, or nullopt: a metric with `use`, or a sequence figure.
std::optional<SweepMeasure> findSweepMeasure(const std::string& name);

struct SweepSpec {
  std::filesystem::path file;
  nlohmann::json document;  // as read, for the shards' identity and for merge
  std::string name, title, citation, note;
  std::map<std::string, std::filesystem::path> scenes;  // id → scene file (absolute)
  SweepSettings settings;
  int repeat = 1;
  SweepAreaLight area;
  // What the table's numbers are: a kSweepMeasure metric (frame_ms: the whole frame as the
  // papers measured it, G-buffer plus every pass of the technique; fps; memory_mb).
  SweepMeasure measure{"frame_ms", &metric("frame_ms"), ""};
  // "all" or "A:B[:STEP]" (as --frames): every cell runs over these frames of its scene.
  std::optional<std::string> frames;
  // "differences": true adds each row's difference to sm in the measure's unit (e.g. ms)
  // beside its ratio: a fixed cost reads as a ratio only against a frame of known size.
  bool differences = false;
  std::vector<SweepColumn> columns;
  std::vector<SweepRow> rows;
  SweepFigure figure;
};

// Reads and validates a spec. Relative scene paths are relative to the spec's folder.
// Technique ids and parameters are checked against the registry (load plugins first).
SweepSpec loadSweepSpec(const std::filesystem::path& file);
// `sceneFilesMustExist` false: for merge, which reads records, not scenes.
SweepSpec parseSweepSpec(const nlohmann::json& document, const std::filesystem::path& file,
                         bool sceneFilesMustExist = true);

}  // namespace testbed
