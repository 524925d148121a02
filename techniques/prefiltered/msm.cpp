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
    // The paper's α = 3e-5 (for its 16-bit quantization) is the default for both storages.
    b.real("moment_bias", momentBias, 3e-5, 0.0, 1e-2,
           "alpha: moments mixed with (0.5, 0.5, 0.5, 0.5) by this amount; 3e-5 is the "
           "paper's value for 16-bit storage");
    // Our addition (the paper's algorithm compares the receiver's depth as is): a lit
    // surface is its own occluder, and with t at its own depth the solve is at its least
    // conditioned, so compiler and ulp differences flip receivers there (dark specks).
    // 1e-4 of the light's depth range puts t in front of the single-depth step by more
    // than the 16-bit moments' rounding (docs/techniques.md, "Moment shadow maps").
    b.real("depth_bias", depthBias, kDefaultDepthBias, 0.0, 1e-2,
           "the receiver's normalized light depth is moved this much towards the light "
           "before the bound (0: the paper's comparison as is)");
    b.choice("storage", quantized, true, {{"16", true}, {"32", false}},
             "16: RGBA16 with the paper's optimized quantization; 32: RGBA32F moments");
    moments.reflect(b);
  }
  static constexpr double kDefaultDepthBias = 1e-4;
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
