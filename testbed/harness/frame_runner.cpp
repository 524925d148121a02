#include "testbed/harness/frame_runner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "testbed/core/error.h"
#include "testbed/harness/shading.h"
#include "testbed/harness/timing.h"
#include "testbed/scene/light_fit.h"

namespace testbed {
namespace {

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
  checkShadowSetup(s.shadowSetup);
  if (s.repeat < 1 || s.repeat > kMaxRepeat)
    throw InputError("--repeat: " + std::to_string(s.repeat) + " is outside 1.." + std::to_string(kMaxRepeat));
}

TechniquePath defaultPath(std::string_view renderer) {
  return isSoftwareRasterizer(renderer) ? TechniquePath::Fast : TechniquePath::Paper;
}

FrameRunner::FrameRunner(const Scene& scene, const RenderSettings& settings)
    : scene_(scene), settings_(settings),
      path_(settings.path.value_or(defaultPath(reinterpret_cast<const char*>(glGetString(GL_RENDERER))))),
      fitCamera_(scene.camera), light_(fittedLightTransforms(scene)), geometry_(scene),
      gbuffer_(settings.size), shading_(settings.size) {
  renderGBuffer();
}

void FrameRunner::lightMoved() {
  light_ = fittedLightTransforms(scene_);
  fitCamera_ = scene_.camera;
}

void FrameRunner::objectsMoved(const std::vector<std::size_t>& objects) { geometry_.update(scene_, objects); }

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
                     light_, settings_.shadowMapSize, settings_.depthFormat, path_,
                     scene_.camera, geometry_.bounds(), settings_.shadowSetup, fitCamera_};
}

TechniqueSession::TechniqueSession(FrameRunner& runner, const RegisteredTechnique& technique,
                                   const ParameterSet& parameters)
    : runner_(runner), info_(*technique.info), id_(technique.info->id) {
  // A declared technique times the passes of the run's path only.
  if (!info_.passes.empty()) timer_.declarePasses(passNamesOn(info_.passes, runner.path()));
  const glm::ivec2 size = runner.settings().size;
  target_.ensure({.size = size, .color = GL_R32F});  // before the ledger: the harness's, not the technique's
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
  glClearTexImage(target_.color().id(), 0, GL_RED, GL_FLOAT, &zero);
  glFinish();
  const auto start = std::chrono::steady_clock::now();
  instance_->render(runner_.inputs(), timer_, VisibilityTarget{target_.framebuffer(), target_.color()});
  glFinish();
  const auto end = std::chrono::steady_clock::now();
  Frame frame{timer_.resolve(), std::chrono::duration<double, std::milli>(end - start).count()};
  checkGlError("rendering technique " + id_);
  return frame;
}

PassTimes TechniqueSession::shadeFrame() {
  PassTimer timer;
  {
    auto scope = timer.scope("shading");
    runner_.shading_.draw(runner_.gbuffer_, runner_.light_, target_.color());
  }
  checkGlError("shading " + id_ + "'s frame");
  return timer.resolve();
}

std::vector<GpuMemoryLedger::Resource> TechniqueSession::memory() const {
  if (info_.passes.empty()) return ledger_.resources();
  const RenderSettings& settings = runner_.settings();
  return declaredMemory(id_, info_.resources, ledger_.resources(),
                        {.screen = settings.size, .shadowMap = settings.shadowMapSize});
}

ImageF TechniqueSession::visibility() const {
  ImageF image = readTopDown(target_.color(), 1);
  const auto& positions = runner_.positions_.pixels;
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    if (positions[i * 4 + 3] < 0.5f) image.pixels[i] = std::numeric_limits<float>::quiet_NaN();
  return image;
}

TechniqueRun FrameRunner::run(const RegisteredTechnique& technique, const ParameterSet& parameters) {
  TechniqueSession session(*this, technique, parameters);
  return run(session, parameters, true);
}

TechniqueRun FrameRunner::run(TechniqueSession& session, const ParameterSet& parameters, bool warmUp) {
  TechniqueRun result;
  result.id = session.id();
  result.params = parameters.toJson();
  if (warmUp) {  // shader compilation and first allocations
    session.renderFrame();
    session.shadeFrame();
  }
  std::vector<PassTimes> times, shading;
  std::vector<double> cpu;
  for (int i = 0; i < settings_.repeat; ++i) {
    const TechniqueSession::Frame frame = session.renderFrame();
    times.push_back(frame.times);
    cpu.push_back(frame.cpuMs);
    shading.push_back(session.shadeFrame());
  }
  result.times = medianPassTimes(times);
  result.shadingTimes = medianPassTimes(shading);
  result.cpuMs = median(cpu);
  result.memoryBytes = session.memoryBytes();
  result.memory = session.memory();
  result.visibility = session.visibility();
  result.debugImages = session.technique().debugImages();
  result.maps = session.technique().shadowMaps();
  return result;
}

ImageF FrameRunner::shade(const ImageF& visibility) const {
  return shadeVisibility(positions_, normals_, light_, visibility);
}

}  // namespace testbed
