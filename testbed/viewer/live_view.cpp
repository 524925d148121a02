#include "testbed/viewer/live_view.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "groundtruth/shadow_volumes.h"
#include "testbed/core/error.h"
#include "testbed/harness/measurement.h"
#include "testbed/harness/record.h"
#include "testbed/harness/sequence.h"
#include "testbed/scene/view.h"

namespace testbed::viewer {
namespace {

constexpr std::size_t kHistoryFrames = 240;  // the live plot's width

// Visibility as grey, pixels without a receiver in the heat map's background grey.
ImageF visibilityImage(const ImageF& visibility) {
  ImageF image = visibility;
  for (float& v : image.pixels) v = std::isnan(v) ? kHeatBackground[0] : v;
  return image;
}

}  // namespace

const char* displayModeName(DisplayMode mode) {
  switch (mode) {
    case DisplayMode::Shaded: return "shaded";
    case DisplayMode::Visibility: return "visibility";
    case DisplayMode::Error: return "error";
    case DisplayMode::SoftError: return "soft-error";
    case DisplayMode::Debug: return "debug";
  }
  return "?";
}

DisplayMode parseDisplayMode(const std::string& name) {
  std::string names;
  for (DisplayMode m : kDisplayModes) {
    if (name == displayModeName(m)) return m;
    names += std::string(names.empty() ? "" : m == DisplayMode::Debug ? " or " : ", ") + displayModeName(m);
  }
  throw InputError("mode: expected " + names + ", got '" + name + "'");
}

LiveView::LiveView(Scene& scene, const RenderSettings& settings, std::string backend)
    : scene_(scene), settings_(settings), backend_(std::move(backend)) {
  settings_.repeat = 1;  // every displayed frame is one timed frame
  rebuildRunner();
}

LiveView::~LiveView() {
  session_.reset();  // before the runner it refers to
}

void LiveView::rebuildRunner() {
  session_.reset();
  runner_.reset();
  runner_ = std::make_unique<FrameRunner>(scene_, settings_);
  ++generation_;
  restartTemporal();
  if (technique_) startSession();
}

void LiveView::startSession() {
  session_.reset();  // its GL objects go before the new ones are booked
  session_ = std::make_unique<TechniqueSession>(*runner_, *technique_, parameters_);
  history_.clear();
  restartTemporal();
}

void LiveView::setTechnique(const RegisteredTechnique& technique, const std::map<std::string, std::string>& assignments) {
  parameters_ = resolveParameters(technique.info->id, technique.info->parameters, assignments);
  technique_ = &technique;
  startSession();
}

void LiveView::setParameters(const std::map<std::string, std::string>& assignments) {
  setTechnique(*technique_, assignments);
}

void LiveView::setShadowMap(int size, DepthFormat format) {
  RenderSettings wanted = settings_;
  wanted.shadowMapSize = size;
  wanted.depthFormat = format;
  validateSettings(wanted);
  settings_ = wanted;
  rebuildRunner();
}

void LiveView::cameraMoved() {
  runner_->renderGBuffer();
  ++generation_;
  restartTemporal();
}

void LiveView::lightMoved() {
  runner_->lightMoved();
  ++generation_;
  restartTemporal();
}

void LiveView::showFrame(int frame) {
  if (!animated()) return;
  frame = std::clamp(frame, 0, animationFrames() - 1);
  if (frame == animationFrame_) return;
  const bool next = frame == animationFrame_ + 1;
  advanceTo(scene_, *runner_, frame);
  animationFrame_ = frame;
  ++generation_;
  if (!next) restartTemporal();
  playbackStale_ = true;
}

// A change that is not the next animation frame (another technique, a moved camera, a jump)
// makes the frames before it no sequence with the ones after: the figures start again.
void LiveView::restartTemporal() {
  temporal_ = TemporalAccumulator();
  playback_ = PlaybackFigures{};
  playback_.firstFrame = animationFrame_;
  playbackStale_ = true;
}

// The shown frame against the ground truth, then added to the running temporal figures,
// exactly as runSequence adds a compared frame.
void LiveView::addToPlayback() {
  playbackStale_ = false;
  const ImageF& truth = groundTruth();
  playback_.note.clear();
  try {
    playback_.error = computeErrorMetrics(visibility_, truth);
  } catch (const std::invalid_argument& error) {
    playback_.error.reset();
    playback_.note = error.what();
  }
  const glm::ivec2 size = settings_.size;
  const glm::mat4 viewProjection = cameraTransforms(scene_.camera, float(size.x) / float(size.y)).viewProjection();
  try {
    temporal_.addFrame(TemporalFrame{animationFrame_, visibility_, truth, runner_->positions(), viewProjection});
  } catch (const std::invalid_argument& error) {
    playback_.note = error.what();
  }
  playback_.temporal = temporal_.result();
}

void LiveView::setMode(DisplayMode mode, std::string debugImage) {
  mode_ = mode;
  debugImage_ = std::move(debugImage);
  if (!visibility_.pixels.empty()) rebuildImage();
}

void LiveView::renderFrame() {
  lastFrame_ = session_->renderFrame();
  visibility_ = session_->visibility();
  debugImages_ = session_->technique().debugImages();
  history_.push_back({lastFrame_.times, lastFrame_.cpuMs});
  if (history_.size() > kHistoryFrames) history_.pop_front();
  ++frames_;
  if (animated() && playbackStale_) addToPlayback();
  rebuildImage();
}

const ImageF& LiveView::groundTruth() {
  if (!truth_ || truthGeneration_ != generation_) {
    const MeasurementEntry entry = groundTruthEntry();
    TechniqueSession truth(*runner_, *entry.technique, entry.parameters);
    truth.renderFrame();
    truth_ = truth.visibility();
    truthGeneration_ = generation_;
  }
  return *truth_;
}

// Rendered only when soft-error mode asks for it: dozens of shadow-volume passes.
const ImageF& LiveView::areaReference() {
  if (!(scene_.light.radius > 0))
    throw std::invalid_argument("the light has no radius (light.radius), so there is no area-light reference");
  if (!area_ || areaGeneration_ != generation_) {
    const RegisteredTechnique& reference = areaLightReference();
    TechniqueSession area(*runner_, reference, resolveParameters("area", reference.info->parameters, {}));
    area.renderFrame();
    area_ = area.visibility();
    areaGeneration_ = generation_;
  }
  return *area_;
}

void LiveView::rebuildImage() {
  imageNote_.clear();
  try {
    switch (mode_) {
      case DisplayMode::Shaded: image_ = runner_->shade(visibility_); return;
      case DisplayMode::Visibility: image_ = visibilityImage(visibility_); return;
      case DisplayMode::Error: image_ = errorHeatMap(visibility_, groundTruth()); return;
      case DisplayMode::SoftError: image_ = softErrorHeatMap(visibility_, areaReference()); return;
      case DisplayMode::Debug:
        for (const auto& [name, debug] : debugImages_) {
          if (debugImage_.empty() || name == debugImage_) {
            image_ = debug;
            return;
          }
        }
        imageNote_ = debugImages_.empty()
                         ? "no debug images: set the technique's debug parameter (if it has one)"
                         : "no debug image named '" + debugImage_ + "'";
        break;
    }
  } catch (const std::invalid_argument& error) {
    imageNote_ = error.what();
  }
  image_ = runner_->shade(visibility_);  // what the mode could not show
}

ErrorMetrics LiveView::errorMetrics() {
  // Soft-error mode adds the soft metrics against the reference its heat map shows.
  const bool soft = mode_ == DisplayMode::SoftError && scene_.light.radius > 0;
  return computeErrorMetrics(visibility_, groundTruth(), soft ? &areaReference() : nullptr);
}

std::uint64_t LiveView::memoryBytes() const { return session_->memoryBytes(); }

nlohmann::json LiveView::record() {
  TechniqueRun run;
  run.id = technique_->info->id;
  run.params = parameters_.toJson();
  run.visibility = visibility_;
  run.times = lastFrame_.times;
  run.cpuMs = lastFrame_.cpuMs;
  run.memoryBytes = memoryBytes();
  Record record = makeRecord(run, *runner_, backend_);
  record.error = errorMetrics();
  nlohmann::json json = record;
  if (!animated()) return json;
  const TemporalMetrics& t = playback_.temporal;
  json["frame"] = animationFrame_;
  json["temporal"] = {{"first_frame", playback_.firstFrame}, {"flicker", t.flicker},
                      {"crawl_pct", t.crawlPct},           {"crawl_missed_pct", t.crawlMissedPct},
                      {"stable_pairs", t.stablePairs},      {"frame_pairs", t.framePairs}};
  return json;
}

}  // namespace testbed::viewer
