// `msm`: moment shadow maps (Peters & Klein 2015): four moments (z, z², z³, z⁴), the
// Hamburger 4MSM lower bound (the paper's Algorithm 3) with moment bias α, stored either
// as 16-bit UNORM through the paper's optimized quantization or as 32-bit floats.
#include "techniques/prefiltered/prefiltered_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

struct MsmParameters {
  float momentBias;
  float depthBias;
  bool quantized;  // storage=16
  MomentsPass::Parameters moments;
  void reflect(ParameterBinder& b) {
    // Both defaults are ours, measured (docs/techniques.md, "Moment shadow maps"): the
    // paper's α = 3e-5 for its 16-bit quantization leaves the 4MSM solve so near-singular
    // that one unit of 16-bit rounding, which a change of compiler or an ulp of the light
    // moves, changes receivers far from any edge by 0.01 to 0.03; α = 1e-4 absorbs it.
    b.real("moment_bias", momentBias, 1e-4, 0.0, 1e-2,
           "alpha: moments mixed with (0.5, 0.5, 0.5, 0.5) by this amount; the paper's value "
           "for 16-bit storage is 3e-5");
    // The paper compares the receiver's depth as is. A lit surface is its own occluder, and
    // with t at its own depth the solve is at its least conditioned: compiler and ulp
    // differences give dark specks there, and with 16-bit storage the rounding alone does
    // where the normalized depth is small (the fence's floor near the light).
    b.real("depth_bias", depthBias, 5e-5, 0.0, 1e-2,
           "the receiver's normalized light depth is moved this much towards the light "
           "before the bound (0: the paper's comparison as is)");
    b.choice("storage", quantized, true, {{"16", true}, {"32", false}},
             "16: RGBA16 with the paper's optimized quantization; 32: RGBA32F moments");
    moments.reflect(b);
  }
};

class MomentShadowMap final : public PrefilteredTechnique<MsmParameters> {
  void configured() override {
    setEncoding(parameters_.quantized ? MomentsFormat{GL_RGBA16, "encodeMsm16", "visibilityMsm16"}
                                      : MomentsFormat{GL_RGBA32F, "encodeMsm32", "visibilityMsm32"},
                glm::vec4(parameters_.momentBias, parameters_.depthBias, 0, 0));
  }
};

TESTBED_REGISTER_TECHNIQUE(MomentShadowMap, .id = "msm", .output = OutputKind::Filtered,
                           .citation = "Peters & Klein, Moment shadow mapping, I3D 2015",
                           .summary = "moment shadow maps: 4 moments, Hamburger 4MSM bound, optimized 16-bit quantization",
                           .passes = prefilteredPasses("four moments of light depth, optionally quantized (Peters & Klein, I3D 2015)", "the Hamburger 4MSM bound (Algorithm 3)"),
                           .resources = prefilteredResources({GL_RGBA16, GL_RGBA32F}));

}  // namespace
}  // namespace testbed
