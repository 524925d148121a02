#pragma once
// The record of one run (docs/record.md "The record"): what `render`, `compare`, `sweep` and the viewer
// write as T.json, metrics.json and records.json, and what `check`, `merge` and the reports
// read back. One typed struct, written and read by nlohmann's to_json / from_json; the
// metrics in it are placed and validated by the metric table (harness/metric_table.h).
#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "testbed/gl/shader_path.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/harness/timing.h"
#include "testbed/render/shadow_map_pass.h"  // LightRecord
#include "testbed/metrics/metrics.h"

namespace testbed {

// One measure (GPU queries or wall time) of a run: per pass and the total of the passes.
struct PassesRecord {
  double totalMs = 0;                       // the metric table's gpu_ms.total / wall_ms.total
  std::map<std::string, double> passesMs;  // by pass name
};

// The area-light reference a record's soft metrics were taken against ("area_reference":
// its samples and the light's radius, docs/ground-truth-and-metrics.md): a sweep's study
// names them, since a spec may replace every scene's radius.
struct AreaReferenceRecord {
  int samples = 0;
  double lightRadius = 0;
  bool operator==(const AreaReferenceRecord&) const = default;
};

struct Record {
  std::string technique, scene;
  int width = 0, height = 0;
  int shadowMap = 0;
  std::string depthFormat;  // "16", "24", "32f"
  nlohmann::json params = nlohmann::json::object();  // the technique's own parameters
  PassesRecord gpu, wall;
  TimingSource timing = TimingSource::Gpu;  // which of gpu and wall is the frame's time
  double cpuMs = 0, gbufferMs = 0;
  // The harness's shading pass after the frame ("shading_ms", harness/shading.h), in the
  // measure `timing` names; in no total. None in records written before it was timed.
  std::optional<double> shadingMs;
  int repeat = 1;
  std::uint64_t triangles = 0, memoryBytes = 0;
  // The run's path ("path": docs/paths.md) and memoryBytes split by resource ("memory":
  // name, format, bytes, role); none in records written before either existed.
  std::optional<TechniquePath> path;
  std::optional<std::vector<GpuMemoryLedger::Resource>> memory;
  // The front-end that compiled the run's shaders ("shader_path"); none in records written
  // before it was recorded, which the driver's GLSL compiler compiled (compiledBy).
  std::optional<ShaderPath> shaderPath;
  LightRecord light;
  std::string backend;
  // The work counters (docs/work-counters.md): "work": null where the GL offers no pipeline
  // statistics; records made before the counters have no "work" key (workRecorded false).
  std::optional<PassWork> work;
  bool workRecorded = true;
  std::optional<ErrorMetrics> error;  // null until compared with the ground truth
  std::optional<AreaReferenceRecord> areaReference;  // with soft metrics, where the run names it
  std::optional<std::size_t> cell;    // a sweep's cell index (records.json only)
  // A sweep cell run over frames (docs/paper-runs.md "Frames"): the sequence record's
  // "frames", "light_fit", "series" and "temporal" blocks; the rest of the record is the
  // last frame's.
  std::optional<nlohmann::json> sequence;

  const PassesRecord& timed() const { return timing == TimingSource::Wall ? wall : gpu; }
};

// The record of a run on `runner`, `error` empty.
Record makeRecord(const TechniqueRun& run, const FrameRunner& runner, const std::string& backend);

// The front-end that compiled the record's shaders: GLSL where the record does not say.
inline ShaderPath compiledBy(const Record& record) { return record.shaderPath.value_or(ShaderPath::Glsl); }

// The technique's frame time in the measure its `timing` names (no G-buffer).
double frameTimeMs(const Record& record);

// Reads a record, checking every field: throws InputError "<where>.<field>: <what>", e.g.
// "runs/metrics.json: [2].error.rmse: missing" for where = "runs/metrics.json: [2]".
Record readRecord(const nlohmann::json& json, const std::string& where);

void to_json(nlohmann::json& json, const Record& record);
// Throws InputError "<field>: <what>" (readRecord adds where the record came from).
void from_json(const nlohmann::json& json, Record& record);
void to_json(nlohmann::json& json, const LightRecord& light);
void from_json(const nlohmann::json& json, LightRecord& light);

}  // namespace testbed
