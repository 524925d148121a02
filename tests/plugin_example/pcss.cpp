// `pcss`: percentage-closer soft shadows (Fernando, "Percentage-Closer Soft Shadows",
// SIGGRAPH 2005 sketch) as an out-of-tree plugin: the example of a soft technique written
// only against the plugin API (docs/writing-a-technique.md "Walk-through: PCSS as a plugin").
// The shared shadow map and the screen pass are ShadowMapScreenTechnique's; the light's
// data and the depth helpers are testbed/glsl/light.glsl's; this file states the
// parameters and the one per-frame number the shader wants from the CPU.
#include <algorithm>
#include <cmath>

#include "testbed/render/receiver_inputs.h"
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/plugin.h"

namespace {

using namespace testbed;

struct PcssParameters {
  int blockerTaps;
  int filterTaps;
  float minFilterTexels;
  float bias;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) {
    b.integer("blocker_taps", blockerTaps, 6, 1, 16, "blocker search: taps a side of its grid");
    b.integer("filter_taps", filterTaps, 8, 1, 24, "filter: taps a side of its grid");
    b.real("min_filter", minFilterTexels, 0.5, 0.0, 16.0, "the filter's least radius in texels (0: a point light's hard edge)");
    reflectShadowTestBias(b, bias);
    shadowMap.reflect(b);
  }
};

// The area light's radius in shadow-map uv (see uLightSizeUv in pcss.frag). Per frame: a
// fitted light's near plane and extent change with the scene.
float lightSizeUv(const FrameInputs& in) {
  const float radius = lightRadiusUniform(in.scene.light);  // world units, or radians for the sun
  if (in.light.orthographic) return std::tan(radius) / (2.0f * in.light.extent);
  const float halfFov = 0.5f * glm::radians(in.light.fovDegrees);
  return radius / (2.0f * in.light.nearPlane * std::tan(halfFov));
}

class PercentageCloserSoftShadows final : public ShadowMapScreenTechnique<PcssParameters> {
 public:
  PercentageCloserSoftShadows() : ShadowMapScreenTechnique("tests/plugin_example/pcss.frag") {}

  void setUniforms(const Program& program, const FrameInputs& in) const override {
    program.set("uBias", parameters_.bias);
    program.set("uBlockerTaps", parameters_.blockerTaps);
    program.set("uFilterTaps", parameters_.filterTaps);
    program.set("uMinFilterTexels", parameters_.minFilterTexels);
    program.set("uLightSizeUv", lightSizeUv(in));
  }
};

}  // namespace

TESTBED_PLUGIN(registrar) {
  registrar.add<PercentageCloserSoftShadows>(
      {.id = "pcss", .output = OutputKind::Filtered,
       .citation = "Fernando, Percentage-Closer Soft Shadows, SIGGRAPH 2005 sketch",
       .summary = "plugin example: blocker search, penumbra estimate, variable-size PCF",
       .passes = PercentageCloserSoftShadows::declaredPasses(
           "blocker search, penumbra estimate and variable-size PCF in one screen pass (Fernando 2005)"),
       .resources = PercentageCloserSoftShadows::declaredResources()});
}
