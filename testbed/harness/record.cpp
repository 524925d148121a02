#include "testbed/harness/record.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "testbed/core/error.h"
#include "testbed/harness/metric_table.h"
#include "testbed/io/json_reader.h"
#include "testbed/render/shadow_map_pass.h"

namespace testbed {
namespace {

using nlohmann::json;

// Every field goes through the one checked reader (io/json_reader.h): its rules for
// numbers, whole numbers and strings, its messages. Records are machine-written, so
// unknown keys are not refused: the metric table and older writers add keys a reader
// of today does not look at.
using Reader = JsonField;

std::string describe(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// Times, error metrics and distances are measured magnitudes: a negative one is a
// corrupt record, not a huge improvement.
double magnitude(const Reader& r) {
  const double v = r.number();
  if (!(v >= 0)) r.fail("expected a non-negative number, got " + describe(v));
  return v;
}

// The value at a metric's JSON pointer ("/error/boundary_px/mean"), its path in messages.
Reader follow(const Reader& at, std::string_view pointer) {
  if (pointer.empty()) return at;
  const std::size_t slash = std::min(pointer.find('/', 1), pointer.size());
  return follow(at[pointer.substr(1, slash - 1)], pointer.substr(slash));
}

bool inErrorBlock(const Metric& m) { return m.path.starts_with("/error/"); }

json passesJson(const PassesRecord& passes) {
  json out = json::object();
  for (const auto& [name, ms] : passes.passesMs) out[name] = ms;
  return out;
}

PassesRecord readPasses(const Reader& times) {
  PassesRecord out;
  const Reader passes = times["passes"];
  if (!passes.json().is_object()) passes.fail("expected an object of pass times");
  for (const auto& name : passes.keys()) out.passesMs[name] = magnitude(passes[name]);
  return out;  // totalMs: the metric table's
}

json memoryJson(const std::vector<GpuMemoryLedger::Resource>& resources) {
  json out = json::array();
  for (const auto& m : resources)
    out.push_back({{"name", m.name}, {"format", m.format}, {"bytes", m.bytes}, {"role", std::string(roleName(m.role))}});
  return out;
}

std::vector<GpuMemoryLedger::Resource> readMemory(const Reader& memory) {
  std::vector<GpuMemoryLedger::Resource> out;
  for (std::size_t i = 0, n = memory.arraySize("an array of resources"); i < n; ++i) {
    const Reader r = memory[i];
    const bool paper = r["role"].word({"paper", "device"}) == 0;
    out.push_back({r["name"].text(), r["format"].text(), paper ? ResourceRole::Paper : ResourceRole::Device,
                   r["bytes"].count()});
  }
  return out;
}

// {"vertex_invocations": n, ...}: one count per work counter.
json countsJson(const WorkCounts& counts) {
  json out = json::object();
  for (std::size_t i = 0; i < counts.size(); ++i) out[std::string(kWorkCounters[i].name)] = counts[i];
  return out;
}

WorkCounts readCounts(const Reader& r) {
  WorkCounts counts{};
  for (std::size_t i = 0; i < counts.size(); ++i) counts[i] = r[kWorkCounters[i].name].count();
  return counts;
}

json workJson(const std::optional<PassWork>& work) {
  if (!work) return nullptr;
  json passes = json::object();
  for (const auto& [name, counts] : work->passes) passes[name] = countsJson(counts);
  return {{"passes", passes}, {"total", countsJson(work->total)}};
}

std::optional<PassWork> readWork(const Reader& record) {
  if (!record.has("work") || record["work"].json().is_null()) return std::nullopt;
  const Reader work = record["work"];
  PassWork out;
  const Reader passes = work["passes"];
  if (!passes.json().is_object()) passes.fail("expected an object of pass counts");
  for (const auto& name : passes.keys()) out.passes[name] = readCounts(passes[name]);
  out.total = readCounts(work["total"]);
  return out;
}

// The error block's pixel counts: each percentage's denominator and the ground truth's
// make-up, so that "3.85 %" can be read as "10 of 260 pixels", and the flag of a ground
// truth that cannot rank techniques (metrics.h groundTruthFlag). Written only where
// counted; records made before have neither key.
constexpr std::array<std::pair<const char*, int ErrorMetrics::*>, 7> kPixelCounts = {{
    {"receivers", &ErrorMetrics::receivers},
    {"gt_lit", &ErrorMetrics::gtLitReceivers},
    {"gt_shadow", &ErrorMetrics::gtShadowReceivers},
    {"gt_boundary", &ErrorMetrics::gtBoundaryPixels},
    {"edge_band", &ErrorMetrics::edgeBandPixels},
    {"far_shadow", &ErrorMetrics::farShadowReceivers},
    {"far_lit", &ErrorMetrics::farLitReceivers},
}};

void writePixelCounts(json& error, const ErrorMetrics& m) {
  if (m.receivers == 0) return;
  json pixels = json::object();
  for (const auto& [name, member] : kPixelCounts) pixels[name] = m.*member;
  // Which count each percentage is taken over.
  pixels["denominators"] = {{"mismatch_pct", "receivers"}, {"edge_mismatch_pct", "edge_band"},
                            {"leak_pct", "far_shadow"}, {"overestimation_pct", "far_lit"}};
  error["pixels"] = pixels;
  const auto flag = groundTruthFlag(m);
  error["flag"] = flag ? json(*flag) : json(nullptr);
}

void readPixelCounts(const Reader& error, ErrorMetrics& m) {
  if (!error.has("pixels")) return;
  const Reader pixels = error["pixels"];
  for (const auto& [name, member] : kPixelCounts) {
    const std::uint64_t count = pixels[name].count();
    if (count > std::uint64_t(std::numeric_limits<int>::max())) pixels[name].fail("more pixels than an image holds");
    m.*member = int(count);
  }
  if (m.receivers == 0) pixels["receivers"].fail("expected at least one receiver");
}

LightRecord readLight(const Reader& r) {
  LightRecord l;
  l.type = r["type"].text();
  l.eye = r["eye"].numbers<3>();
  l.nearPlane = r["near"].number();
  l.farPlane = r["far"].number();
  if (r.has("fov")) l.fov = r["fov"].number();
  if (r.has("extent")) l.extent = r["extent"].number();
  l.fitted = r["fitted"].boolean();
  l.depthStepWorld = r["depth_step_world"].numbers<2>();
  l.texelWorld = r["texel_world"].numbers<2>();
  if (r.has("offset_world")) l.offsetWorld = r["offset_world"].numbers<2>();
  if (r.has("split")) l.split = r["split"].numbers<2>();
  if (r.has("maps")) {
    const Reader maps = r["maps"];
    for (std::size_t i = 0, n = maps.arraySize(); i < n; ++i) l.maps.push_back(readLight(maps[i]));
  }
  if (r.has("setup")) {
    const Reader setup = r["setup"];
    l.setup = LightRecord::Setup{int(setup["cascades"].count()), setup["splits"].text(), setup["fit"].text(),
                                 setup.has("bias") ? setup["bias"].text() : "slope",
                                 setup.has("blend_band") ? setup["blend_band"].number() : 0.0};
  }
  return l;
}

Record read(const Reader& r) {
  if (!r.json().is_object()) r.fail("expected an object (a record)");
  Record out;
  out.technique = r["technique"].text();
  out.scene = r["scene"].text();
  const Reader size = r["size"];
  size.arrayOf(2, "[width, height]");
  out.width = size[0].integer(0, std::numeric_limits<int>::max());
  out.height = size[1].integer(0, std::numeric_limits<int>::max());
  out.shadowMap = int(r["shadow_map"].count());
  out.depthFormat = r["depth_format"].text();
  const Reader params = r["params"];
  out.params = params.object().json();
  out.backend = r["backend"].text();
  out.timing = r["timing"].word({"gpu", "wall"}) == 1 ? TimingSource::Wall : TimingSource::Gpu;
  out.gpu = readPasses(r["gpu_ms"]);
  out.wall = readPasses(r["wall_ms"]);
  out.repeat = int(r["repeat"].count());
  out.triangles = r["triangles"].count();
  out.light = readLight(r["light"]);
  out.workRecorded = r.has("work");
  out.work = readWork(r);
  const Reader error = r["error"];
  if (!error.json().is_null() && !error.json().is_object()) error.fail("expected an object or null, got " + error.brief());
  if (r.has("cell")) out.cell = std::size_t(r["cell"].count());
  if (r.has("shading_ms")) out.shadingMs = magnitude(r["shading_ms"]);
  if (r.has("sequence")) {
    const Reader sequence = r["sequence"];
    if (!sequence.has("series")) sequence.fail("expected an object with \"series\"");
    out.sequence = sequence.json();
  }
  if (r.has("area_reference")) {
    const Reader area = r["area_reference"];
    out.areaReference = AreaReferenceRecord{area["samples"].integer(1, 4096), magnitude(area["light_radius"])};
  }
  if (r.has("path")) {
    out.path = parsePath(r["path"].text());
    if (!out.path) r["path"].fail("expected \"paper\" or \"fast\"");
  }
  if (r.has("memory")) out.memory = readMemory(r["memory"]);
  if (r.has("shader_path")) {
    out.shaderPath = parseShaderPath(r["shader_path"].text());
    if (!out.shaderPath) r["shader_path"].fail("expected \"glsl\" or \"spirv\"");
  }
  for (const Metric& m : metricTable()) {
    if (m.path.empty() || (inErrorBlock(m) && error.json().is_null())) continue;
    // A soft metric without a reference has no key (soft_rmse: null).
    if (m.reference == MetricReference::Soft && !r.json().contains(json::json_pointer(std::string(m.path)))) continue;
    const Reader value = follow(r, m.path);
    if (m.nullable && value.json().is_null()) continue;
    m.store(out, m.integer ? double(value.count()) : magnitude(value));
  }
  if (!error.json().is_null() && !out.error) out.error.emplace();  // an error block of no metric: impossible today
  if (out.error) readPixelCounts(error, *out.error);
  std::uint64_t split = 0;
  for (const auto& m : out.memory.value_or(std::vector<GpuMemoryLedger::Resource>{})) split += m.bytes;
  if (out.memory && split != out.memoryBytes)
    r["memory"].fail("its bytes sum to " + std::to_string(split) + ", memory_bytes is " + std::to_string(out.memoryBytes));
  return out;
}

}  // namespace

Record makeRecord(const TechniqueRun& run, const FrameRunner& runner, const std::string& backend) {
  const RenderSettings& s = runner.settings();
  Record r;
  r.technique = run.id;
  r.scene = runner.scene().name;
  r.width = s.size.x;
  r.height = s.size.y;
  r.shadowMap = s.shadowMapSize;
  r.depthFormat = depthFormatName(s.depthFormat);
  r.params = run.params;
  for (const auto& name : run.times.order) {
    r.gpu.passesMs[name] = run.times.passMs.at(name);
    r.wall.passesMs[name] = run.times.wallPassMs.at(name);
  }
  r.gpu.totalMs = run.times.totalMs;
  r.wall.totalMs = run.times.wallTotalMs;
  r.timing = timingSourceFor(backend);
  r.cpuMs = run.cpuMs;
  r.gbufferMs = frameTimeMs(runner.gbufferTimes(), r.timing);
  if (!run.shadingTimes.order.empty()) r.shadingMs = frameTimeMs(run.shadingTimes, r.timing);
  r.repeat = s.repeat;
  r.triangles = runner.triangleCount();
  r.memoryBytes = run.memoryBytes;
  r.memory = run.memory;
  r.path = runner.path();
  r.shaderPath = shaderPath();
  r.work = run.times.work;
  r.light = lightSetupRecord(runner.light(), s.shadowMapSize, s.depthFormat, run.params, run.maps,
                             s.shadowSetup.bias);
  if (!s.shadowSetup.isDefault())
    r.light.setup = LightRecord::Setup{s.shadowSetup.cascades, s.shadowSetup.splitsWord(), s.shadowSetup.fitWord(),
                                       s.shadowSetup.biasWord(), s.shadowSetup.blendBand};
  r.backend = backend;
  return r;
}

double frameTimeMs(const Record& record) { return record.timed().totalMs; }

// `where` is the record's place, to which the reader appends each field's path.
Record readRecord(const json& value, const std::string& where) { return read(Reader(value, "", where)); }

void from_json(const json& value, Record& record) { record = read(Reader(value, "", "")); }

void to_json(json& out, const LightRecord& l) {
  out = {{"type", l.type},
         {"eye", json::array({l.eye[0], l.eye[1], l.eye[2]})},
         {"near", l.nearPlane},
         {"far", l.farPlane},
         {"fitted", l.fitted},
         {"depth_step_world", json::array({l.depthStepWorld[0], l.depthStepWorld[1]})},
         {"texel_world", json::array({l.texelWorld[0], l.texelWorld[1]})}};
  if (l.fov) out["fov"] = *l.fov;
  if (l.extent) out["extent"] = *l.extent;
  if (l.offsetWorld) out["offset_world"] = json::array({(*l.offsetWorld)[0], (*l.offsetWorld)[1]});
  if (l.split) out["split"] = json::array({(*l.split)[0], (*l.split)[1]});
  if (!l.maps.empty()) out["maps"] = l.maps;
  if (l.setup)
    out["setup"] = {
        {"cascades", l.setup->cascades}, {"splits", l.setup->splits}, {"fit", l.setup->fit}, {"bias", l.setup->bias}};
  if (l.setup && l.setup->blendBand > 0) out["setup"]["blend_band"] = l.setup->blendBand;
}

void from_json(const json& value, LightRecord& light) { light = readLight(Reader(value, "", "light")); }

void to_json(json& out, const Record& r) {
  out = {{"technique", r.technique},
         {"scene", r.scene},
         {"size", json::array({r.width, r.height})},
         {"shadow_map", r.shadowMap},
         {"depth_format", r.depthFormat},
         {"params", r.params},
         {"gpu_ms", {{"passes", passesJson(r.gpu)}}},
         {"wall_ms", {{"passes", passesJson(r.wall)}}},
         {"timing", std::string(timingName(r.timing))},
         {"repeat", r.repeat},
         {"triangles", r.triangles},
         {"light", r.light},
         {"backend", r.backend},
         {"error", nullptr}};
  if (r.cell) out["cell"] = *r.cell;
  if (r.shadingMs) out["shading_ms"] = *r.shadingMs;
  if (r.sequence) out["sequence"] = *r.sequence;
  if (r.areaReference)
    out["area_reference"] = {{"samples", r.areaReference->samples}, {"light_radius", r.areaReference->lightRadius}};
  if (r.path) out["path"] = std::string(pathName(*r.path));
  if (r.shaderPath) out["shader_path"] = std::string(shaderPathName(*r.shaderPath));
  if (r.memory) out["memory"] = memoryJson(*r.memory);
  if (r.workRecorded) out["work"] = workJson(r.work);
  bool soft = false;  // measured against the area-light reference too
  for (const Metric& m : metricTable()) {
    if (m.path.empty() || (inErrorBlock(m) && !r.error)) continue;
    const std::optional<double> v = m.value(r, nullptr);
    soft = soft || (v && m.reference == MetricReference::Soft);
    if (!v && !m.nullable) continue;  // a metric this run did not measure has no key
    out[json::json_pointer(std::string(m.path))] =
        !v ? json(nullptr) : m.integer ? json(std::uint64_t(*v)) : json(*v);
  }
  if (r.error) writePixelCounts(out["error"], *r.error);
  // The derived figures, computed here once so that readers take them as written; reading
  // recomputes them from the stored ones.
  for (const Metric& m : metricTable())
    if (m.shownIn(kCarried))
      if (const std::optional<double> v = m.value(r, nullptr)) out[json::json_pointer(recordPath(m))] = *v;
  // With two references in play, the error block names each measured metric's
  // (metric_table.h MetricReference); with the ground truth alone every metric is its.
  if (soft)
    for (const Metric& m : metricTable())
      if (m.reference != MetricReference::None && m.value(r, nullptr))
        out["error"]["reference"][std::string(m.name)] = referenceName(m.reference);
}

}  // namespace testbed
