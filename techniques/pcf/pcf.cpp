// `pcf`: percentage-closer filtering (Reeves, Salesin, Cook 1987) — the fraction of a
// k×k block of binary depth tests around the receiver's texel that is lit. Filtering the
// test results (never the depths) is what keeps it free of the light leaks of
// pre-filtered maps. Optionally each tap is bilinearly weighted ("bilinear PCF").
#include "testbed/render/shadow_map_screen_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

struct PcfParameters {
  int kernel;
  bool bilinear;
  float bias;
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) {
    // Odd so the block is centred on the receiver's texel.
    b.integer("kernel", kernel, 3, 1, 31, "filter width k in texels (k×k taps, odd)").oddOnly();
    b.boolean("bilinear", bilinear, false, "weight each tap bilinearly over its 4 nearest texels ((k+1)² tests)");
    reflectShadowTestBias(b, bias);
    shadowMap.reflect(b);
  }
};

class PercentageCloserFiltering final : public ShadowMapScreenTechnique<PcfParameters> {
 public:
  PercentageCloserFiltering() : ShadowMapScreenTechnique("techniques/pcf/pcf_visibility.frag") {}

  void setUniforms(const Program& program, const FrameInputs&) const override {
    program.set("uBias", parameters_.bias);
    program.set("uKernel", parameters_.kernel);
    program.set("uBilinear", parameters_.bilinear ? 1 : 0);
  }
};

TESTBED_REGISTER_TECHNIQUE(PercentageCloserFiltering, .id = "pcf", .output = OutputKind::Filtered,
                           .citation = "Reeves, Salesin, Cook, Rendering antialiased shadows with depth maps, SIGGRAPH 1987",
                           .summary = "percentage-closer filtering: fraction of k×k nearest depth tests that are lit",
                           .passes = PercentageCloserFiltering::withCascadePasses(PercentageCloserFiltering::declaredPasses(
                               "k×k depth tests averaged (Reeves, Salesin & Cook, SIGGRAPH 1987)")),
                           .resources = PercentageCloserFiltering::declaredResources(), .cascades = {.supported = true});

}  // namespace
}  // namespace testbed
