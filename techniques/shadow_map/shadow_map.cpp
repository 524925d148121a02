// `sm`: plain shadow mapping (Williams 1978) — one binary depth test per pixel against
// the nearest-filtered map. The baseline every ratio in the reports is taken against.
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

class PlainShadowMap final : public ShadowMapScreenTechnique {
 public:
  struct Parameters {
    float bias;
    ShadowMapPass::Parameters shadowMap;
    void reflect(ParameterBinder& b) {
      reflectShadowTestBias(b, bias);
      shadowMap.reflect(b);
    }
  };

  PlainShadowMap() : ShadowMapScreenTechnique("techniques/shadow_map/shadow_map_visibility.frag") {}

  static TechniqueInfo describe() {
    return {.id = "sm",
            .output = OutputKind::Hard,
            .citation = "Williams, Casting curved shadows on curved surfaces, SIGGRAPH 1978",
            .summary = "plain shadow mapping: one nearest depth test per pixel",
            .parameters = declaredParameters<Parameters>()};
  }

  void configure(const ParameterSet& values) override {
    bindParameters(values, parameters_);
    configureShadowMap(parameters_.shadowMap);
  }
  void setUniforms(const Program& program) const override { program.set("uBias", parameters_.bias); }

 private:
  Parameters parameters_{};
};

}  // namespace

TESTBED_REGISTER_TECHNIQUE(PlainShadowMap);

}  // namespace testbed
