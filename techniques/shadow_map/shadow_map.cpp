// `sm`: plain shadow mapping (Williams 1978) — one binary depth test per pixel against
// the nearest-filtered map. The baseline every ratio in the reports is taken against.
#include "testbed/render/receiver_inputs.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

class PlainShadowMap final : public ShadowTechnique {
 public:
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

  void configure(const ParameterSet& parameters) override {
    shadowMap_.configure(parameters);
    bias_ = static_cast<float>(parameters.getFloat("bias"));
  }

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override {
    if (!program_)
      program_ = Program::graphics("testbed/render/fullscreen.vert",
                                   "techniques/shadow_map/shadow_map_visibility.frag");
    shadowMap_.render(in, timer);
    auto scope = timer.scope("visibility");
    bindReceiverInputs(program_, in);
    bindShadowMap(program_, shadowMap_.depth());
    program_.set("uBias", bias_);
    screen_.draw(program_, out.framebuffer, in.size);
  }

 private:
  ShadowMapPass shadowMap_;
  ScreenPass screen_;
  Program program_;
  float bias_ = 0.0f;
};

}  // namespace

TESTBED_REGISTER_TECHNIQUE(PlainShadowMap);

}  // namespace testbed
