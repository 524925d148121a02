// `sm`: plain shadow mapping (Williams 1978) — one binary depth test per pixel against
// the nearest-filtered map. The baseline every ratio in the reports is taken against.
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

struct PlainShadowMapParameters {
  float bias;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) {
    reflectShadowTestBias(b, bias);
    shadowMap.reflect(b);
  }
};

class PlainShadowMap final : public ShadowMapScreenTechnique<PlainShadowMapParameters> {
 public:
  PlainShadowMap() : ShadowMapScreenTechnique("techniques/shadow_map/shadow_map_visibility.frag") {}
  void setUniforms(const Program& program, const FrameInputs&) const override { program.set("uBias", parameters_.bias); }
};

TESTBED_REGISTER_TECHNIQUE(PlainShadowMap, .id = "sm", .output = OutputKind::Hard,
                           .citation = "Williams, Casting curved shadows on curved surfaces, SIGGRAPH 1978",
                           .summary = "plain shadow mapping: one nearest depth test per pixel",
                           .passes = PlainShadowMap::withCascadePasses(
                               PlainShadowMap::declaredPasses("the depth test per pixel (Williams, SIGGRAPH 1978)")),
                           .resources = PlainShadowMap::declaredResources(), .cascades = {.supported = true});

}  // namespace
}  // namespace testbed
