#pragma once
// The plugin interface every shadow technique implements (docs/writing-a-technique.md "Writing a technique").
// A technique turns the frame's inputs into a screen-space visibility buffer: 1 = lit,
// 0 = shadowed, in between for filtered techniques; receivers whose normal faces away
// from the light are shadowed (glsl/receiver.glsl does that for every technique).
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/io/image_io.h"
#include "testbed/gl/depth_format.h"
#include "testbed/scene/scene.h"
#include "testbed/scene/view.h"
#include "testbed/technique/declaration.h"
#include "testbed/technique/light_crop.h"
#include "testbed/technique/parameter_binder.h"
#include "testbed/technique/parameters.h"
#include "testbed/technique/path.h"
#include "testbed/technique/shadow_setup.h"

namespace testbed {

class GpuScene;
class GBuffer;

enum class OutputKind { Hard, Filtered };

// Whether a technique renders the run's shadow-map set-up (shadow_setup.h) beyond its
// default, one map fitted to the scene: sm and pcf do, through the shared shadow map
// (render/shadow_map_screen_technique.h); the others read the one map of the light and say
// so, and asking them for cascades is bad input naming `reason` (docs/techniques.md).
struct CascadeSupport {
  bool supported = false;
  std::string reason = "its passes read the light's one shadow map, not the cascade array; not ported yet";
};

// A technique's registration (registry.h) gives id, output, citation, summary, passes and
// resources as designated initializers and adds family and parameters; every member has an
// initializer.
struct TechniqueInfo {
  std::string id{};        // CLI name: "sm", "smsr", "rpcf-rsmss"
  std::string family{};    // the technique's folder, "shadow_map": set at registration (registry.h)
  OutputKind output = OutputKind::Hard;
  std::string citation{};  // "Williams 1978"
  std::string summary{};   // one line for `testbed list`
  // Every pass it times and every resource it allocates, on either path (declaration.h).
  std::vector<PassDeclaration> passes{};
  std::vector<ResourceDeclaration> resources{};
  CascadeSupport cascades{};
  std::vector<ParameterSpec> parameters{};  // declaredParameters<P>() of its parameter struct
};

struct FrameInputs {
  const Scene& scene;
  const GpuScene& geometry;
  const GBuffer& gbuffer;
  glm::ivec2 size;              // screen size in pixels
  ViewProjection camera;
  LightTransforms light;
  int shadowMapSize = 1024;
  DepthFormat depthFormat = DepthFormat::D16;
  // The run's path (path.h): a technique whose paper structure differs from its fast one
  // renders the one asked for, with the same visibility.
  TechniquePath path = TechniquePath::Paper;
  // What `camera` is made of (cameraTransforms, scene/view.h): eye, target, up, vertical
  // fov and the near and far view depths; the aspect is size.x / size.y. With
  // cameraFrustumSlice (light_crop.h) a technique gets the world corners of a depth range.
  CameraDesc cameraSetup{};
  // Every triangle's vertices as they are this frame, bounded once per upload (moved
  // objects bound again), not per frame.
  WorldBounds sceneBounds{};
  // The run's shadow-map set-up (--cascades, --splits, --fit) and the camera its maps are
  // fitted to: the frame's camera, except in a held view (docs/motion.md), which shows the
  // previous frame's set-up, fitted to the previous camera, through this frame's camera.
  ShadowSetup shadowSetup{};
  CameraDesc fitCamera{};

  float aspect() const { return float(size.x) / float(size.y); }
};

// One shadow map of a technique's last frame, for the record's light block, which lists them
// as `maps` (render/shadow_map_pass.h lightSetupRecord): the transforms it was rendered with
// (a cascade's cropped light, croppedLight in light_crop.h) and, for a map that serves a
// range of the camera's view depths (a cascade), that range.
struct ShadowMapUse {
  LightTransforms light;
  std::optional<std::array<double, 2>> split;
};

// Where the technique writes its visibility: an R32F texture of the screen's size with a
// framebuffer already attached. Background pixels are masked by the harness afterwards.
struct VisibilityTarget {
  const Framebuffer& framebuffer;
  const Texture& texture;
};

class ShadowTechnique {
 public:
  virtual ~ShadowTechnique() = default;
  // Called once with the validated parameters, before the first render. Techniques with
  // parameters derive WithParameters (with_parameters.h), which implements it.
  virtual void configure(const ParameterSet& parameters) = 0;
  // Renders one frame. Every GPU pass runs inside a `timer.scope("name")` of a pass its
  // TechniqueInfo declares. GL objects may be (re)allocated here, each under the
  // GpuMemoryLedger::Label of a declared resource; their bytes are booked as this
  // technique's memory.
  virtual void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) = 0;
  // Colour images for people, e.g. a revectorization technique's discontinuity space
  // (`--set debug=discontinuity`): name → RGB image (top-down) of the last frame. `render`
  // writes each as T.<name>.png. Empty unless a parameter asked for them.
  virtual std::vector<std::pair<std::string, ImageF>> debugImages() const { return {}; }
  // The maps of the last frame when they are not the one map of the frame's light (cascades):
  // the record lists each (light.maps). Empty, the default: one map of in.light.
  virtual std::vector<ShadowMapUse> shadowMaps() const { return {}; }
};

// Throws InputError naming the technique, the option and its reason when `setup` is not the
// default and the technique does not support it (CascadeSupport).
void requireCascadeSupport(const TechniqueInfo& info, const ShadowSetup& setup);

using TechniqueFactory = std::function<std::unique_ptr<ShadowTechnique>()>;

}  // namespace testbed
