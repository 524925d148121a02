#include "testbed/harness/frame_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/scene/light_fit.h"

namespace testbed {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

// GL rows are bottom-up; files and metrics use top-down.
ImageF readTopDown(const Texture& texture, int channels) {
  ImageF image;
  image.width = texture.width();
  image.height = texture.height();
  image.channels = channels;
  const std::vector<float> raw = texture.readFloats(channels);
  image.pixels.resize(raw.size());
  const std::size_t row = std::size_t(image.width) * channels;
  for (int y = 0; y < image.height; ++y)
    std::copy_n(raw.begin() + std::ptrdiff_t((image.height - 1 - y) * row), row,
                image.pixels.begin() + std::ptrdiff_t(y * row));
  return image;
}

float aspectOf(glm::ivec2 size) { return float(size.x) / float(size.y); }

}  // namespace

void validateSettings(const RenderSettings& s) {
  GLint maxTexture = 0, maxViewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxViewport);
  const int screenLimit = std::min({kMaxScreenSide, maxTexture, maxViewport[0], maxViewport[1]});
  if (s.size.x < 1 || s.size.y < 1 || s.size.x > screenLimit || s.size.y > screenLimit)
    throw InputError("--size: " + std::to_string(s.size.x) + "x" + std::to_string(s.size.y) +
                     " is outside 1.." + std::to_string(screenLimit) + " per side");
  const int mapLimit = std::min({kMaxShadowMapSize, maxTexture, maxViewport[0], maxViewport[1]});
  if (s.shadowMapSize < 1 || s.shadowMapSize > mapLimit)
    throw InputError("--shadow-map: " + std::to_string(s.shadowMapSize) + " is outside 1.." +
                     std::to_string(mapLimit));
  if (s.repeat < 1 || s.repeat > kMaxRepeat)
    throw InputError("--repeat: " + std::to_string(s.repeat) + " is outside 1.." + std::to_string(kMaxRepeat));
}

FrameRunner::FrameRunner(const Scene& scene, const RenderSettings& settings)
    : scene_(scene), settings_(settings), light_(fittedLightTransforms(scene)), geometry_(scene),
      gbuffer_(settings.size) {
  renderGBuffer();
}

void FrameRunner::lightMoved() { light_ = fittedLightTransforms(scene_); }

void FrameRunner::renderGBuffer() {
  PassTimer timer;
  {
    auto scope = timer.scope("gbuffer");
    gbuffer_.render(geometry_, cameraTransforms(scene_.camera, aspectOf(settings_.size)));
  }
  gbufferTimes_ = timer.resolve();
  checkGlError("rendering the G-buffer");
  positions_ = readTopDown(gbuffer_.position(), 4);
  normals_ = readTopDown(gbuffer_.shadingNormal(), 3);
}

FrameRunner::~FrameRunner() = default;

FrameInputs FrameRunner::inputs() const {
  return FrameInputs{scene_, geometry_, gbuffer_, settings_.size,
                     cameraTransforms(scene_.camera, aspectOf(settings_.size)),
                     light_, settings_.shadowMapSize, settings_.depthFormat};
}

TechniqueSession::TechniqueSession(FrameRunner& runner, const RegisteredTechnique& technique,
                                   const ParameterSet& parameters)
    : runner_(runner), id_(technique.info->id) {
  const glm::ivec2 size = runner.settings().size;
  visibility_ = Texture::create2D(GL_R32F, size.x, size.y);
  target_ = Framebuffer::create();
  target_.attachColor(0, visibility_);
  target_.finish({0});
  // Everything the technique allocates, now or while rendering, is booked in its ledger.
  GpuMemoryLedger::Scope booking(ledger_);
  instance_ = technique.create();
  instance_->configure(parameters);
}

TechniqueSession::~TechniqueSession() {
  GpuMemoryLedger::Scope booking(ledger_);
  instance_.reset();
}

TechniqueSession::Frame TechniqueSession::renderFrame() {
  GpuMemoryLedger::Scope booking(ledger_);
  const float zero = 0.0f;
  glClearTexImage(visibility_.id(), 0, GL_RED, GL_FLOAT, &zero);
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  instance_->render(runner_.inputs(), timer_, VisibilityTarget{target_, visibility_});
  glFinish();
  const auto end = std::chrono::steady_clock::now();
  Frame frame{timer_.resolve(), std::chrono::duration<double, std::milli>(end - start).count()};
  checkGlError("rendering technique " + id_);
  return frame;
}

ImageF TechniqueSession::visibility() const {
  ImageF image = readTopDown(visibility_, 1);
  const auto& positions = runner_.positions_.pixels;
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    if (positions[i * 4 + 3] < 0.5f) image.pixels[i] = std::numeric_limits<float>::quiet_NaN();
  return image;
}

TechniqueRun FrameRunner::run(const RegisteredTechnique& technique, const ParameterSet& parameters) {
  TechniqueRun result;
  result.id = technique.info->id;
  result.params = parameters.toJson();
  TechniqueSession session(*this, technique, parameters);
  session.renderFrame();  // warm-up: shader compilation and first allocations
  std::vector<TechniqueSession::Frame> frames;
  for (int i = 0; i < settings_.repeat; ++i) frames.push_back(session.renderFrame());

  std::vector<double> totals, wallTotals, cpu;
  for (const auto& f : frames) {
    totals.push_back(f.times.totalMs);
    wallTotals.push_back(f.times.wallTotalMs);
    cpu.push_back(f.cpuMs);
  }
  result.times.totalMs = median(totals);
  result.times.wallTotalMs = median(wallTotals);
  result.times.order = frames.front().times.order;
  for (const auto& name : result.times.order) {
    std::vector<double> values, wall;
    for (const auto& f : frames) {
      values.push_back(f.times.passMs.at(name));
      wall.push_back(f.times.wallPassMs.at(name));
    }
    result.times.passMs[name] = median(values);
    result.times.wallPassMs[name] = median(wall);
  }
  result.cpuMs = median(cpu);
  result.memoryBytes = session.memoryBytes();
  result.visibility = session.visibility();
  result.debugImages = session.technique().debugImages();
  return result;
}

ImageF FrameRunner::shade(const ImageF& visibility) const {
  constexpr float kAmbient = 0.15f, kAlbedo = 0.85f;
  const glm::vec3 background(0.18f, 0.2f, 0.24f);
  const LightTransforms& light = light_;
  ImageF image;
  image.width = visibility.width;
  image.height = visibility.height;
  image.channels = 3;
  image.pixels.resize(std::size_t(image.width) * image.height * 3);
  for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i) {
    glm::vec3 color = background;
    if (positions_.pixels[i * 4 + 3] >= 0.5f) {
      const glm::vec3 p(positions_.pixels[i * 4], positions_.pixels[i * 4 + 1], positions_.pixels[i * 4 + 2]);
      const glm::vec3 n(normals_.pixels[i * 3], normals_.pixels[i * 3 + 1], normals_.pixels[i * 3 + 2]);
      const glm::vec3 l = light.orthographic ? -light.direction : glm::normalize(light.position - p);
      const float v = std::clamp(visibility.pixels[i], 0.0f, 1.0f);
      color = glm::vec3(kAlbedo * (kAmbient + (1.0f - kAmbient) * std::max(glm::dot(n, l), 0.0f) * v));
    }
    for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = color[c];
  }
  return image;
}

TimingSource timingSourceFor(std::string_view backend) {
  for (const char* software : {"llvmpipe", "softpipe", "swrast"})
    if (backend.find(software) != std::string_view::npos) return TimingSource::Wall;
  return TimingSource::Gpu;
}

double frameTimeMs(const PassTimes& times, TimingSource source) {
  return source == TimingSource::Wall ? times.wallTotalMs : times.totalMs;
}

double frameTimeMs(const nlohmann::json& record) {
  return record.at(record.at("timing") == "wall" ? "wall_ms" : "gpu_ms").at("total").get<double>();
}

nlohmann::json makeRecord(const TechniqueRun& run, const FrameRunner& runner, const std::string& backend) {
  nlohmann::json passes = nlohmann::json::object(), wallPasses = nlohmann::json::object();
  for (const auto& name : run.times.order) {
    passes[name] = run.times.passMs.at(name);
    wallPasses[name] = run.times.wallPassMs.at(name);
  }
  const RenderSettings& s = runner.settings();
  return {
      {"technique", run.id},
      {"scene", runner.scene().name},
      {"size", {s.size.x, s.size.y}},
      {"shadow_map", s.shadowMapSize},
      {"depth_format", depthFormatName(s.depthFormat)},
      {"params", run.params},
      {"gpu_ms", {{"total", run.times.totalMs}, {"passes", passes}}},
      {"wall_ms", {{"total", run.times.wallTotalMs}, {"passes", wallPasses}}},
      {"cpu_ms", run.cpuMs},
      {"gbuffer_ms", frameTimeMs(runner.gbufferTimes(), timingSourceFor(backend))},
      {"timing", timingSourceFor(backend) == TimingSource::Wall ? "wall" : "gpu"},
      {"repeat", s.repeat},
      {"triangles", runner.triangleCount()},
      {"memory_bytes", run.memoryBytes},
      {"light", lightSetupRecord(runner.light(), s.shadowMapSize, s.depthFormat, run.params)},
      {"backend", backend},
      {"error", nullptr},
  };
}

}  // namespace testbed
