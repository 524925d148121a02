// `sm`: plain shadow mapping (Williams 1978) — one binary depth test per pixel against
// the nearest-filtered map. The baseline every ratio in the reports is taken against.
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

class PlainShadowMap final : public ShadowMapScreenTechnique {
 public:
  PlainShadowMap() : ShadowMapScreenTechnique("techniques/shadow_map/shadow_map_visibility.frag") {}

  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "sm";
      i.family = "shadow_map";
      i.output = OutputKind::Hard;
      i.citation = "Williams, Casting curved shadows on curved surfaces, SIGGRAPH 1978";
      i.summary = "plain shadow mapping: one nearest depth test per pixel";
      i.parameters = {ParameterSpec::real("bias", 0.0, -1.0, 1.0,
                                          "constant depth bias subtracted from the receiver's light depth")};
      for (auto& spec : ShadowMapPass::parameters()) i.parameters.push_back(spec);
      return i;
    }();
    return info;
  }

  const TechniqueInfo& info() const override { return staticInfo(); }

  void configureOwn(const ParameterSet& parameters) override {
    bias_ = static_cast<float>(parameters.getFloat("bias"));
  }
  void setUniforms(const Program& program) const override { program.set("uBias", bias_); }

 private:
  float bias_ = 0.0f;
};

}  // namespace

TESTBED_REGISTER_TECHNIQUE(PlainShadowMap);

}  // namespace testbed
