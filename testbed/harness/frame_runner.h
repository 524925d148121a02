#pragma once
// The frame loop around techniques: uploads a scene, renders the G-buffer, runs a technique
// for a warm-up frame plus `repeat` timed frames, and reads back its visibility. What a run
// becomes on disk is harness/record.h; how frames are timed, harness/timing.h.
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "testbed/gl/pass_timer.h"
#include "testbed/gl/render_target.h"
#include "testbed/io/image_io.h"
#include "testbed/gl/depth_format.h"
#include "testbed/harness/shading.h"
#include "testbed/render/gbuffer_pass.h"
#include "testbed/render/gpu_scene.h"
#include "testbed/scene/scene.h"
#include "testbed/scene/view.h"
#include "testbed/technique/registry.h"

namespace testbed {

struct RenderSettings {
  glm::ivec2 size{1280, 720};
  int shadowMapSize = 1024;
  DepthFormat depthFormat = DepthFormat::D16;
  int repeat = 1;  // timed frames after the warm-up frame; times are medians (timing.h)
  std::optional<TechniquePath> path;  // none: defaultPath of the context's renderer
  ShadowSetup shadowSetup{};  // --cascades, --splits, --fit (technique/shadow_setup.h)
};

// The path a run takes unless told (docs/paths.md): `fast` on a software rasterizer, whose
// devices it was made for, `paper` on a GPU.
TechniquePath defaultPath(std::string_view renderer);

// Upper bounds that keep a typo (--size 100000x100000) from exhausting the machine.
inline constexpr int kMaxScreenSide = 8192;
inline constexpr int kMaxShadowMapSize = 16384;
inline constexpr int kMaxRepeat = 10000;

// Throws InputError naming the option for sizes outside [1, max] or beyond the GL limits
// of the current context.
void validateSettings(const RenderSettings& settings);

struct TechniqueRun {
  std::string id;
  nlohmann::json params;
  ImageF visibility;         // one channel, top-down, NaN where no receiver
  PassTimes times;           // medians over the timed frames (medianPassTimes)
  PassTimes shadingTimes;    // the harness's shading pass after each of them (shading.h), medians
  double cpuMs = 0;          // median wall time of a frame, glFinish to glFinish
  std::uint64_t memoryBytes = 0;
  std::vector<GpuMemoryLedger::Resource> memory;  // memoryBytes split by resource
  std::vector<std::pair<std::string, ImageF>> debugImages;  // ShadowTechnique::debugImages()
  std::vector<ShadowMapUse> maps;  // ShadowTechnique::shadowMaps() of the last frame
};

class FrameRunner;

// One technique instance bound to a runner: its visibility target, its memory ledger and
// its timer. The benchmark drives frames one by one; FrameRunner::run() uses it too.
class TechniqueSession {
 public:
  TechniqueSession(FrameRunner& runner, const RegisteredTechnique& technique, const ParameterSet& parameters);
  ~TechniqueSession();

  struct Frame {
    PassTimes times;
    double cpuMs = 0;
  };
  Frame renderFrame();
  // The harness's shading pass (shading.h) over the last frame's visibility, timed on its own
  // as "shading": the papers' frames end with it, the technique's passes do not include it.
  PassTimes shadeFrame();
  std::uint64_t memoryBytes() const { return ledger_.bytes(); }
  // memoryBytes() split by resource, each checked against the technique's declaration
  // (technique/declaration.h: throws DeclarationError on an undeclared allocation).
  std::vector<GpuMemoryLedger::Resource> memory() const;
  // Reads the last frame's visibility: one channel, top-down, NaN where no receiver.
  ImageF visibility() const;
  const ShadowTechnique& technique() const { return *instance_; }
  const std::string& id() const { return id_; }

 private:
  FrameRunner& runner_;
  const TechniqueInfo& info_;
  GpuMemoryLedger ledger_;
  RenderTarget target_;  // its colour: the visibility, R32F
  PassTimer timer_;
  std::unique_ptr<ShadowTechnique> instance_;
  std::string id_;
};

class FrameRunner {
 public:
  // Needs a current GL context. The scene is read by reference on every frame: after its
  // camera changes, call renderGBuffer(); after its light changes, lightMoved().
  FrameRunner(const Scene& scene, const RenderSettings& settings);
  // A temporary scene would dangle: the runner reads it on every frame.
  FrameRunner(const Scene&& scene, const RenderSettings& settings) = delete;
  ~FrameRunner();

  TechniqueRun run(const RegisteredTechnique& technique, const ParameterSet& parameters);
  // The same on a session kept across frames (an animation): a warm-up frame when asked,
  // then `repeat` timed frames of the scene as it is now.
  TechniqueRun run(TechniqueSession& session, const ParameterSet& parameters, bool warmUp);
  // Shaded image for people: Lambert × visibility plus ambient, RGB (harness/shading.h).
  ImageF shade(const ImageF& visibility) const;

  // Renders and reads back the G-buffer from the scene's current camera (the constructor
  // does it once; the viewer again whenever the camera moves).
  void renderGBuffer();
  // Fits the light's transforms to the scene's current light again (scene/light_fit.h), and
  // the shadow-map set-up (its cascades) to the scene's current camera.
  void lightMoved();
  // Uploads again the meshes of these objects, moved by an animation (scene/animation.h).
  void objectsMoved(const std::vector<std::size_t>& objects);

  const Scene& scene() const { return scene_; }
  const RenderSettings& settings() const { return settings_; }
  // The run's path: the settings' or, without one, defaultPath of the context's renderer.
  TechniquePath path() const { return path_; }
  const PassTimes& gbufferTimes() const { return gbufferTimes_; }
  // The light's transforms every technique renders with (fitted, scene/light_fit.h).
  const LightTransforms& light() const { return light_; }
  std::size_t triangleCount() const { return geometry_.triangleCount(); }
  // The last shading pass's image (RGBA8, bottom-up; TechniqueSession::shadeFrame).
  const Texture& shadedFrame() const { return shading_.color(); }
  // G-buffer readback, top-down: xyz world position, w coverage.
  const ImageF& positions() const { return positions_; }

 private:
  friend class TechniqueSession;
  FrameInputs inputs() const;

  const Scene& scene_;
  RenderSettings settings_;
  TechniquePath path_;
  // The camera the shadow-map set-up is fitted to: refitted with the light (lightMoved), so a
  // held view (docs/motion.md) renders the previous frame's maps through a new camera.
  CameraDesc fitCamera_;
  LightTransforms light_;
  GpuScene geometry_;
  GBuffer gbuffer_;
  PassTimes gbufferTimes_;
  // Its target is the harness's, allocated with the runner and booked to no technique.
  ShadingPass shading_;
  ImageF positions_, normals_;  // G-buffer readback for shading, top-down
};

}  // namespace testbed
