// `pcf`: percentage-closer filtering (Reeves, Salesin, Cook 1987) — the fraction of a
// k×k block of binary depth tests around the receiver's texel that is lit. Filtering the
// test results (never the depths) is what keeps it free of the light leaks of
// pre-filtered maps. Optionally each tap is bilinearly weighted ("bilinear PCF").
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

class PercentageCloserFiltering final : public ShadowMapScreenTechnique {
 public:
  PercentageCloserFiltering() : ShadowMapScreenTechnique("techniques/pcf/pcf_visibility.frag") {}

  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "pcf";
      i.family = "pcf";
      i.output = OutputKind::Filtered;
      i.citation = "Reeves, Salesin, Cook, Rendering antialiased shadows with depth maps, SIGGRAPH 1987";
      i.summary = "percentage-closer filtering: fraction of k×k nearest depth tests that are lit";
      auto kernel = ParameterSpec::integer("kernel", 3, 1, 31, "filter width k in texels (k×k taps, odd)");
      kernel.oddOnly = true;  // odd so the block is centred on the receiver's texel
      i.parameters = {
          kernel,
          ParameterSpec::boolean("bilinear", false,
                                 "weight each tap bilinearly over its 4 nearest texels ((k+1)² tests)"),
          ParameterSpec::real("bias", 0.0, -1.0, 1.0,
                              "constant depth bias subtracted from the receiver's light depth"),
      };
      for (auto& spec : ShadowMapPass::parameters()) i.parameters.push_back(spec);
      return i;
    }();
    return info;
  }

  const TechniqueInfo& info() const override { return staticInfo(); }

  void configureOwn(const ParameterSet& parameters) override {
    kernel_ = static_cast<int>(parameters.getInt("kernel"));
    bilinear_ = parameters.getBool("bilinear");
    bias_ = static_cast<float>(parameters.getFloat("bias"));
  }

  void setUniforms(const Program& program) const override {
    program.set("uBias", bias_);
    program.set("uKernel", kernel_);
    program.set("uBilinear", bilinear_ ? 1 : 0);
  }

 private:
  int kernel_ = 3;
  bool bilinear_ = false;
  float bias_ = 0.0f;
};

}  // namespace

TESTBED_REGISTER_TECHNIQUE(PercentageCloserFiltering);

}  // namespace testbed
