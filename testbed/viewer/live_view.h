#pragma once
// What the viewer shows, through the same harness as `render`: a FrameRunner over the
// viewer's scene and a TechniqueSession of the chosen technique, one frame per call, with
// the image of the chosen display mode. The shaded image is FrameRunner::shade() of the
// session's visibility, byte for byte what `render` writes as T.png.
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "testbed/harness/frame_runner.h"
#include "testbed/harness/timing.h"
#include "testbed/metrics/metrics.h"
#include "testbed/metrics/temporal_metrics.h"
#include "testbed/scene/animation.h"

namespace testbed::viewer {

// SoftError: the heat map against the area-light reference (`compare --reference soft`).
enum class DisplayMode { Shaded, Visibility, Error, SoftError, Debug };
inline constexpr DisplayMode kDisplayModes[] = {DisplayMode::Shaded, DisplayMode::Visibility, DisplayMode::Error,
                                               DisplayMode::SoftError, DisplayMode::Debug};
const char* displayModeName(DisplayMode mode);
DisplayMode parseDisplayMode(const std::string& name);  // "shaded", ...; throws InputError

// An animated scene's figures as it is played: the shown frame's error against the ground
// truth and the temporal figures pooled over the frames shown one after the other
// (TemporalAccumulator, the code `compare --frames` uses).
struct PlaybackFigures {
  int firstFrame = 0;                  // where the running figures started
  std::optional<ErrorMetrics> error;   // of the shown frame; none when it has no receiver
  std::string note;                    // why there is no error (or no temporal figure)
  TemporalMetrics temporal;            // pooled since firstFrame
};

struct FrameSample {
  PassTimes times;
  double cpuMs = 0;
};

class LiveView {
 public:
  // `scene` is the viewer's own copy (camera and light change); needs a current context.
  LiveView(Scene& scene, const RenderSettings& settings, std::string backend);
  ~LiveView();

  // Throws InputError (as --set) for a bad assignment; the view keeps its technique then.
  void setTechnique(const RegisteredTechnique& technique, const std::map<std::string, std::string>& assignments);
  void setParameters(const std::map<std::string, std::string>& assignments);
  void setShadowMap(int size, DepthFormat format);
  // Call after changing the scene's camera / light.
  void cameraMoved();
  void lightMoved();

  // An animated scene: moves it to `frame` (clamped to its frames) as `compare --frames`
  // does (advanceTo). The running temporal figures go on when `frame` is the one after the
  // shown frame and start again from it otherwise. No-op without animation.
  void showFrame(int frame);
  bool animated() const { return scene_.animation != nullptr; }
  int animationFrame() const { return animationFrame_; }
  int animationFrames() const { return animated() ? scene_.animation->frames : 1; }
  // Up to date after renderFrame() (the first frame it renders of each animation frame).
  const PlaybackFigures& playback() const { return playback_; }

  void setMode(DisplayMode mode, std::string debugImage = {});
  DisplayMode mode() const { return mode_; }
  const std::string& debugImageName() const { return debugImage_; }

  // Renders one frame of the technique and rebuilds the displayed image.
  void renderFrame();
  std::uint64_t framesRendered() const { return frames_; }

  // The displayed image (RGB, or one channel in visibility mode; top-down). In error mode
  // it is the heat map against the shadow volumes, in soft-error mode against the area-light
  // reference (its default samples); in debug mode the named debug image.
  const ImageF& image() const { return image_; }
  // Why the image is not what the mode asks for (no debug image, no receiver, ...); empty if it is.
  const std::string& imageNote() const { return imageNote_; }
  const ImageF& visibility() const { return visibility_; }
  const std::vector<std::pair<std::string, ImageF>>& debugImages() const { return debugImages_; }

  // Error metrics of the last frame against the ground truth (rendered if stale); in
  // soft-error mode, with a light radius, also the soft ones against the area-light
  // reference. Throws std::invalid_argument when the frame has no receiver or NaN on one.
  ErrorMetrics errorMetrics();
  // The record `render` would write for this frame, with its error block; an animated
  // scene's also with "frame" and "temporal" (the running figures, as sequence records
  // name them, plus first_frame).
  nlohmann::json record();

  const Scene& scene() const { return scene_; }
  const RenderSettings& settings() const { return settings_; }
  const RegisteredTechnique& technique() const { return *technique_; }
  const ParameterSet& parameters() const { return parameters_; }
  const std::string& backend() const { return backend_; }
  TimingSource timingSource() const { return timingSourceFor(backend_); }
  std::uint64_t memoryBytes() const;
  const std::deque<FrameSample>& history() const { return history_; }
  // Grows by one whenever the camera, light or settings change (stamps metrics).
  std::uint64_t viewGeneration() const { return generation_; }

 private:
  void rebuildRunner();
  void startSession();
  const ImageF& groundTruth();
  const ImageF& areaReference();
  void rebuildImage();
  void restartTemporal();
  void addToPlayback();

  Scene& scene_;
  RenderSettings settings_;
  std::string backend_;
  std::unique_ptr<FrameRunner> runner_;
  const RegisteredTechnique* technique_ = nullptr;
  ParameterSet parameters_;
  std::unique_ptr<TechniqueSession> session_;
  TechniqueSession::Frame lastFrame_;

  ImageF visibility_, image_;
  std::vector<std::pair<std::string, ImageF>> debugImages_;
  std::string imageNote_;
  DisplayMode mode_ = DisplayMode::Shaded;
  std::string debugImage_;

  std::optional<ImageF> truth_;
  std::optional<ImageF> area_;
  std::uint64_t truthGeneration_ = 0, areaGeneration_ = 0, generation_ = 1, frames_ = 0;
  std::deque<FrameSample> history_;

  int animationFrame_ = 0;
  bool playbackStale_ = true;  // the shown animation frame is not in playback_ yet
  TemporalAccumulator temporal_;
  PlaybackFigures playback_;
};

}  // namespace testbed::viewer
