#pragma once
// The depth-only shadow map shared by techniques: nearest filtering, clamp to border with
// border depth 0 so lookups outside the light's frustum read as shadow (the papers'
// convention), polygon offset while rendering (default factor 4, units 20, the papers').
// The offset counts depth-buffer steps, so its world size follows the light's depth range,
// which the harness fits to the scene (scene/light_fit.h); every record states it.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/technique/declaration.h"
#include "testbed/gl/render_target.h"
#include "testbed/gl/depth_format.h"
#include "testbed/render/gpu_scene.h"
#include "testbed/scene/view.h"
#include "testbed/technique/parameter_binder.h"
#include "testbed/technique/technique.h"

namespace testbed {

// The polygon offset's defaults as ShadowMapPass::Parameters::reflect declares them: the
// papers' (factor 4, units 20) unless a technique asks for others.
struct PolygonOffsetDefaults {
  double factor = 4.0;
  double units = 20.0;
};

class ShadowMapPass {
 public:
  // The pass's parameters: a technique that uses the pass holds them and reflects them
  // after its own, so they are declared once, here; `defaults` changes only the defaults
  // (`shadowMap.reflect(b, {.factor = 1.5, .units = 4})`), names, ranges and help stay.
  struct Parameters {
    float offsetFactor, offsetUnits;
    void reflect(ParameterBinder& b, PolygonOffsetDefaults defaults = {});
  };
  void configure(const Parameters& parameters) { parameters_ = parameters; }
  // The polygon offset a bias mode applies of the technique's (docs/cascades.md "Bias
  // modes"): all of it with the slope bias; the constant term only with the normal offset,
  // which replaces the slope term; none with the receiver-plane bias, whose plane and
  // constant replace both.
  static Parameters appliedOffset(const Parameters& parameters, BiasMode bias);

  // Its pass and its map as the techniques that use it declare them (declaration.h). A
  // technique rendering several maps (cascades) declares a pass per render it times
  // separately: declaredPass("cascade-0", "split 0's map (Zhang et al. 2006)").
  static PassDeclaration declaredPass();
  static PassDeclaration declaredPass(std::string name, std::string paperStep);
  static ResourceDeclaration declaredMap();

  // 0 (the default): the map is one 2D texture (sampler2D). n ≥ 1: a 2D array texture of n
  // layers (sampler2DArray), each rendered by its own render() call (cascades); the ledger
  // counts an array as n maps (SizeRule::ShadowMap), at most kMostTexturesOfASize.
  void setLayers(int layers) { layers_ = layers; }
  int layers() const { return layers_; }

  // Renders the frame's light (in.light) into the map, timed as "shadow-map".
  void render(const FrameInputs& in, PassTimer& timer);
  // Renders the depth seen through `light` (any view and projection: the frame's light, a
  // cascade's cropped one) into layer `layer` of the map (0 for a 2D map), timed as `pass`,
  // a pass the technique declares. (Re)allocates the texture when size, format or layers
  // change. Border depth 0 and the polygon offset as for the frame's light.
  void render(const FrameInputs& in, const ViewProjection& light, const std::string& pass, PassTimer& timer,
              int layer = 0);
  // The map: a 2D texture, or the array of setLayers(n ≥ 1).
  const Texture& depth() const { return layers_ > 0 ? array_ : target_.depth(); }

 private:
  // The framebuffer that draws into `layer` of a map of the frame's size and format,
  // (re)allocated under the map's label when they changed.
  GLuint ensureTarget(const FrameInputs& in, int layer);

  Parameters parameters_{};
  int layers_ = 0;
  RenderTarget target_;  // the depth map (a 2D texture)
  // The layers' texture and one framebuffer each (layers_ ≥ 1).
  Texture array_;
  std::vector<Framebuffer> layerFramebuffers_;
  Program program_, floatProgram_;  // floatProgram_: 32f depth, the constant offset in the shader
};

// One step of a 16-bit depth buffer in window depth: the unit of `offset_units`.
inline constexpr float kDepthStep16 = 1.0f / 65536.0f;

// The record's "light" block (harness/record.h writes and reads it): the transforms used
// and what they amount to in world units along the light's rays at the near and far
// plane: one depth step, one shadow-map texel and, for a technique with the polygon
// offset, the offset for a surface at 45° to the light (units·step + factor·texel).
struct LightRecord {
  std::string type;  // "spot" or "directional"
  std::array<double, 3> eye{};
  double nearPlane = 0, farPlane = 0;
  std::optional<double> fov, extent;  // a spot light's fov, a directional light's extent
  bool fitted = false;
  std::array<double, 2> depthStepWorld{}, texelWorld{};
  std::optional<std::array<double, 2>> offsetWorld;  // techniques with a polygon offset
  std::optional<std::array<double, 2>> split;  // a map of `maps` serving these camera view depths
  // The maps a technique reported (ShadowTechnique::shadowMaps(), technique.h), each
  // described like the light; none (the JSON has no "maps"): the one map of the light.
  std::vector<LightRecord> maps;
  // The shadow-map set-up (technique/shadow_setup.h) where it is not the default: "setup":
  // {"cascades", "splits", "fit", "bias"}; none, one map fitted to the scene with the slope
  // bias. A record without "bias" (before the bias modes) had the slope bias.
  struct Setup {
    int cascades = 1;
    std::string splits, fit;
    std::string bias = "slope";  // ShadowSetup::biasWord()
    double blendBand = 0;        // "blend_band", written where not 0
  };
  std::optional<Setup> setup;
};
// `bias`: the run's bias mode, which decides what of the technique's polygon offset is
// applied (appliedOffset) and so what offset_world states.
LightRecord lightSetupRecord(const LightTransforms& light, int shadowMapSize, DepthFormat format,
                             const nlohmann::json& params, const std::vector<ShadowMapUse>& maps = {},
                             BiasMode bias = BiasMode::Slope);

// `bias` of glsl/shadow_test.glsl (uBias), shared by every technique that uses the test.
void reflectShadowTestBias(ParameterBinder& b, float& bias);

// Uniforms and binding of glsl/shadow_test.glsl: the shadow map on texture unit 2.
void bindShadowMap(const Program& program, const Texture& shadowMap);
// Any map (a cascade array, a technique's own) on texture unit `unit` of units.glsl, its
// sampler uniform `sampler` set to it: bindMap(program, "uCascades", kPluginTextureUnit0, maps).
void bindMap(const Program& program, const char* sampler, int unit, const Texture& map);

}  // namespace testbed
