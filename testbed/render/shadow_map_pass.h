#pragma once
// The depth-only shadow map shared by techniques: nearest filtering, clamp to border with
// border depth 0 so lookups outside the light's frustum read as shadow (the papers'
// convention), polygon offset while rendering (default factor 4, units 20, the papers').
// The offset counts depth-buffer steps, so its world size follows the light's depth range,
// which the harness fits to the scene (scene/light_fit.h); every record states it.
#include <array>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/technique/declaration.h"
#include "testbed/gl/render_target.h"
#include "testbed/gl/depth_format.h"
#include "testbed/render/gpu_scene.h"
#include "testbed/scene/view.h"
#include "testbed/technique/parameter_binder.h"

namespace testbed {

struct FrameInputs;

class ShadowMapPass {
 public:
  // The pass's parameters: a technique that uses the pass holds them and reflects them
  // after its own, so they are declared once, here.
  struct Parameters {
    float offsetFactor, offsetUnits;
    void reflect(ParameterBinder& b);
  };
  void configure(const Parameters& parameters) { parameters_ = parameters; }

  // Its pass and its map as the techniques that use it declare them (declaration.h).
  static PassDeclaration declaredPass();
  static ResourceDeclaration declaredMap();

  // Renders the light's depth into the map (timed as "shadow-map"); (re)allocates the
  // texture when size or format change.
  void render(const FrameInputs& in, PassTimer& timer);
  const Texture& depth() const { return target_.depth(); }

 private:
  Parameters parameters_{};
  RenderTarget target_;  // the depth map
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
};
LightRecord lightSetupRecord(const LightTransforms& light, int shadowMapSize, DepthFormat format,
                                const nlohmann::json& params);

// `bias` of glsl/shadow_test.glsl (uBias), shared by every technique that uses the test.
void reflectShadowTestBias(ParameterBinder& b, float& bias);

// Uniforms and binding of glsl/shadow_test.glsl: the shadow map on texture unit 2.
void bindShadowMap(const Program& program, const Texture& shadowMap);

}  // namespace testbed
