// `vsm`: variance shadow maps (Donnelly & Lauritzen 2006): the mean and mean square of the
// light depth, filtered; visibility is Chebyshev's upper bound σ²/(σ² + (t − μ)²).
#include "techniques/prefiltered/prefiltered_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

struct VsmParameters {
  float minVariance, bleedReduction;
  MomentsPass::Parameters moments;
  void reflect(ParameterBinder& b) {
    // min_variance 1e-6 (σ = 0.1% of the light's near-far range): ten times the float
    // rounding of E[z²] − E[z]² at depth 1. Measured on the bundled scenes: 0 shows acne
    // (bunny, dragon_sun), 1e-7..1e-6 none, 1e-4 starts to blur the fence's shadows.
    b.real("min_variance", minVariance, 1e-6, 0.0, 1e-2, "variance floor in normalized linear light depth (sigma^2)");
    b.real("bleed_reduction", bleedReduction, 0.0, 0.0, 0.99,
           "light-bleeding reduction: linstep(amount, 1, p_max); 0 = plain VSM");
    moments.reflect(b);
  }
};

class VarianceShadowMap final : public PrefilteredTechnique<VsmParameters> {
  void configured() override {
    setEncoding(MomentsFormat{GL_RG32F, "encodeVsm", "visibilityVsm"},
                glm::vec4(parameters_.minVariance, parameters_.bleedReduction, 0, 0));
  }
};

TESTBED_REGISTER_TECHNIQUE(VarianceShadowMap, .id = "vsm", .output = OutputKind::Filtered,
                           .citation = "Donnelly & Lauritzen, Variance shadow maps, I3D 2006",
                           .summary = "variance shadow maps: (z, z^2) in RG32F, Gaussian-filtered; Chebyshev upper bound",
                           .passes = prefilteredPasses("the mean and mean square of light depth (Donnelly & Lauritzen, I3D 2006)", "Chebyshev's upper bound"),
                           .resources = prefilteredResources({GL_RG32F}));

}  // namespace
}  // namespace testbed
