// `evsm`: exponential variance shadow maps (Lauritzen & McCool 2008): Chebyshev's bound on
// exponentially warped depth, positive warp exp(c⁺·z) and negative −exp(−c⁻·z) with z
// mapped to [−1, 1]; with four moments the smaller of the two bounds.
#include "techniques/prefiltered/prefiltered_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

struct EvsmParameters {
  float positiveExponent, negativeExponent;
  int momentCount;  // 2 or 4
  float minVariance, bleedReduction;
  MomentsPass::Parameters moments;
  void reflect(ParameterBinder& b) {
    // 32-bit floats as in the paper. The second moment exp(2c) must fit a float with room
    // for the variance plus (t − μ)² of Chebyshev's denominator: c ≤ 42 (exp(84) ≈ 3e36).
    b.real("positive_exponent", positiveExponent, 40.0, 1.0, 42.0, "c+ of the warp exp(c+ z), z in [-1, 1]");
    b.real("negative_exponent", negativeExponent, 5.0, 1.0, 42.0, "c- of the warp -exp(-c- z), z in [-1, 1]");
    b.choice("moments", momentCount, 4, {{"2", 2}, {"4", 4}},
             "2: positive warp only (RG32F); 4: both warps, min of the bounds (RGBA32F)");
    b.real("min_variance", minVariance, 1e-6, 0.0, 1e-3,  // as vsm's, see vsm.cpp
           "variance floor in normalized linear depth, scaled by each warp's slope");
    b.real("bleed_reduction", bleedReduction, 0.0, 0.0, 0.99,
           "light-bleeding reduction: linstep(amount, 1, p_max); 0 = none");
    moments.reflect(b);
  }
};

class ExponentialVarianceShadowMap final : public PrefilteredTechnique<EvsmParameters> {
  void configured() override {
    const EvsmParameters& p = parameters_;
    setEncoding(p.momentCount == 4 ? MomentsFormat{GL_RGBA32F, "encodeEvsm4", "visibilityEvsm4"}
                                   : MomentsFormat{GL_RG32F, "encodeEvsm2", "visibilityEvsm2"},
                glm::vec4(p.positiveExponent, p.negativeExponent, p.minVariance, p.bleedReduction));
  }
};

TESTBED_REGISTER_TECHNIQUE(ExponentialVarianceShadowMap, .id = "evsm", .output = OutputKind::Filtered,
                           .citation = "Lauritzen & McCool, Layered variance shadow maps, GI 2008",
                           .summary = "exponential variance shadow maps: Chebyshev on exp-warped depth, 32-bit float",
                           .passes = prefilteredPasses("the moments of exponentially warped depth (Lauritzen & McCool, GI 2008)", "Chebyshev's bound on each warp"),
                           .resources = prefilteredResources({GL_RG32F, GL_RGBA32F}));

}  // namespace
}  // namespace testbed
