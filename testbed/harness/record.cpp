#include "testbed/harness/record.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "testbed/core/error.h"
#include "testbed/harness/metric_table.h"
#include "testbed/render/shadow_map_pass.h"

namespace testbed {
namespace {

using nlohmann::json;

// A field that is missing or mistyped; `field` is its path in the record ("error.rmse").
struct BadField {
  std::string field, what;
};

std::string describe(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// A JSON value and its path in the record, for messages.
struct Reader {
  const json& value;
  std::string path;

  Reader(const json& v, std::string p) : value(v), path(std::move(p)) {}

  std::string at(std::string_view key) const { return path.empty() ? std::string(key) : path + "." + std::string(key); }
  [[noreturn]] void fail(const std::string& what) const { throw BadField{path, what}; }
  bool has(std::string_view key) const { return value.is_object() && value.contains(key); }
  Reader operator[](std::string_view key) const {
    if (!value.is_object()) fail("expected an object");
    const auto it = value.find(key);
    if (it == value.end()) throw BadField{at(key), "missing"};
    return {*it, at(key)};
  }
  std::string text() const {
    if (!value.is_string()) fail("expected a string");
    return value.get<std::string>();
  }
  double number() const {
    if (!value.is_number()) fail("expected a number");
    return value.get<double>();
  }
  // Times, error metrics and distances are measured magnitudes: a negative one is a
  // corrupt record, not a huge improvement.
  double magnitude() const {
    const double v = number();
    if (!(v >= 0)) fail("expected a non-negative number, got " + describe(v));
    return v;
  }
  std::uint64_t count() const {
    // A parsed file holds unsigned numbers; a record built in code may hold signed ones.
    if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0))
      fail("expected a non-negative integer");
    return value.get<std::uint64_t>();
  }
  bool boolean() const {
    if (!value.is_boolean()) fail("expected true or false");
    return value.get<bool>();
  }
  template <std::size_t N>
  std::array<double, N> numbers() const {
    if (!value.is_array() || value.size() != N) fail("expected an array of " + std::to_string(N) + " numbers");
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = Reader{value[i], path + "[" + std::to_string(i) + "]"}.number();
    return out;
  }
};

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
  if (!passes.value.is_object()) passes.fail("expected an object of pass times");
  for (const auto& [name, ms] : passes.value.items()) out.passesMs[name] = passes[name].magnitude();
  return out;  // totalMs: the metric table's
}

json memoryJson(const std::vector<GpuMemoryLedger::Resource>& resources) {
  json out = json::array();
  for (const auto& m : resources)
    out.push_back({{"name", m.name}, {"format", m.format}, {"bytes", m.bytes}, {"role", std::string(roleName(m.role))}});
  return out;
}

std::vector<GpuMemoryLedger::Resource> readMemory(const Reader& memory) {
  if (!memory.value.is_array()) memory.fail("expected an array of resources");
  std::vector<GpuMemoryLedger::Resource> out;
  for (std::size_t i = 0; i < memory.value.size(); ++i) {
    const Reader r{memory.value[i], memory.path + "[" + std::to_string(i) + "]"};
    const std::string role = r["role"].text();
    if (role != "paper" && role != "device") r["role"].fail("expected \"paper\" or \"device\"");
    out.push_back({r["name"].text(), r["format"].text(), role == "paper" ? ResourceRole::Paper : ResourceRole::Device,
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
  if (!record.has("work") || record["work"].value.is_null()) return std::nullopt;
  const Reader work = record["work"];
  PassWork out;
  const Reader passes = work["passes"];
  if (!passes.value.is_object()) passes.fail("expected an object of pass counts");
  for (const auto& [name, counts] : passes.value.items()) out.passes[name] = readCounts(passes[name]);
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
    if (!maps.value.is_array()) maps.fail("expected an array");
    for (std::size_t i = 0; i < maps.value.size(); ++i)
      l.maps.push_back(readLight(Reader{maps.value[i], maps.path + "[" + std::to_string(i) + "]"}));
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
  if (!r.value.is_object()) r.fail("expected an object (a record)");
  Record out;
  out.technique = r["technique"].text();
  out.scene = r["scene"].text();
  const Reader size = r["size"];
  if (!size.value.is_array() || size.value.size() != 2 || !size.value[0].is_number_integer() ||
      !size.value[1].is_number_integer())
    size.fail("expected [width, height]");
  out.width = size.value[0].get<int>();
  out.height = size.value[1].get<int>();
  out.shadowMap = int(r["shadow_map"].count());
  out.depthFormat = r["depth_format"].text();
  const Reader params = r["params"];
  if (!params.value.is_object()) params.fail("expected an object");
  out.params = params.value;
  out.backend = r["backend"].text();
  const std::string timing = r["timing"].text();
  if (timing != "gpu" && timing != "wall") r["timing"].fail("expected \"gpu\" or \"wall\"");
  out.timing = timing == "wall" ? TimingSource::Wall : TimingSource::Gpu;
  out.gpu = readPasses(r["gpu_ms"]);
  out.wall = readPasses(r["wall_ms"]);
  out.repeat = int(r["repeat"].count());
  out.triangles = r["triangles"].count();
  out.light = readLight(r["light"]);
  out.workRecorded = r.has("work");
  out.work = readWork(r);
  const Reader error = r["error"];
  if (!error.value.is_null() && !error.value.is_object()) error.fail("expected an object or null");
  if (r.has("cell")) out.cell = std::size_t(r["cell"].count());
  if (r.has("shading_ms")) out.shadingMs = r["shading_ms"].magnitude();
  if (r.has("sequence")) {
    const Reader sequence = r["sequence"];
    if (!sequence.value.is_object() || !sequence.has("series")) sequence.fail("expected an object with \"series\"");
    out.sequence = sequence.value;
  }
  if (r.has("area_reference")) {
    const Reader area = r["area_reference"];
    const std::uint64_t samples = area["samples"].count();
    if (samples < 1 || samples > 4096) area["samples"].fail("expected 1..4096");
    out.areaReference = AreaReferenceRecord{int(samples), area["light_radius"].magnitude()};
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
    if (m.path.empty() || (inErrorBlock(m) && error.value.is_null())) continue;
    // A soft metric without a reference has no key (soft_rmse: null).
    if (m.reference == MetricReference::Soft && !r.value.contains(json::json_pointer(std::string(m.path)))) continue;
    const Reader value = follow(r, m.path);
    if (m.nullable && value.value.is_null()) continue;
    m.store(out, m.integer ? double(value.count()) : value.magnitude());
  }
  if (!error.value.is_null() && !out.error) out.error.emplace();  // an error block of no metric: impossible today
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

Record readRecord(const json& value, const std::string& where) {
  try {
    return read(Reader{value, ""});
  } catch (const BadField& bad) {
    throw InputError(where + (bad.field.empty() ? "" : "." + bad.field) + ": " + bad.what);
  }
}

void from_json(const json& value, Record& record) {
  try {
    record = read(Reader{value, ""});
  } catch (const BadField& bad) {
    throw InputError((bad.field.empty() ? "record" : bad.field) + ": " + bad.what);
  }
}

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

void from_json(const json& value, LightRecord& light) {
  try {
    light = readLight(Reader{value, ""});
  } catch (const BadField& bad) {
    throw InputError("light" + (bad.field.empty() ? "" : "." + bad.field) + ": " + bad.what);
  }
}

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
