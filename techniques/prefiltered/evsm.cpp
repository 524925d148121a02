// `evsm`: exponential variance shadow maps (Lauritzen & McCool 2008): Chebyshev's bound on
// exponentially warped depth, positive warp exp(c⁺·z) and negative −exp(−c⁻·z) with z
// mapped to [−1, 1]; with four moments the smaller of the two bounds.
#include "techniques/prefiltered/prefiltered_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

class ExponentialVarianceShadowMap final : public PrefilteredTechnique {
 public:
  struct Parameters {
    float positiveExponent, negativeExponent;
    int moments;  // 2 or 4
    float minVariance, bleedReduction;
    MomentsPass::Parameters momentsPass;
    void reflect(ParameterBinder& b) {
      // 32-bit floats as in the paper. The second moment exp(2c) must fit a float with room
      // for the variance plus (t − μ)² of Chebyshev's denominator: c ≤ 42 (exp(84) ≈ 3e36).
      b.real("positive_exponent", positiveExponent, 40.0, 1.0, 42.0, "c+ of the warp exp(c+ z), z in [-1, 1]");
      b.real("negative_exponent", negativeExponent, 5.0, 1.0, 42.0, "c- of the warp -exp(-c- z), z in [-1, 1]");
      b.choice("moments", moments, 4, {{"2", 2}, {"4", 4}},
               "2: positive warp only (RG32F); 4: both warps, min of the bounds (RGBA32F)");
      b.real("min_variance", minVariance, 1e-6, 0.0, 1e-3,  // as vsm's, see vsm.cpp
             "variance floor in normalized linear depth, scaled by each warp's slope");
      b.real("bleed_reduction", bleedReduction, 0.0, 0.0, 0.99,
             "light-bleeding reduction: linstep(amount, 1, p_max); 0 = none");
      momentsPass.reflect(b);
    }
  };

  static TechniqueInfo describe() {
    return {.id = "evsm",
            .output = OutputKind::Filtered,
            .citation = "Lauritzen & McCool, Layered variance shadow maps, GI 2008",
            .summary = "exponential variance shadow maps: Chebyshev on exp-warped depth, 32-bit float",
            .parameters = declaredParameters<Parameters>()};
  }

  void configure(const ParameterSet& values) override {
    Parameters p{};
    bindParameters(values, p);
    configureShared(p.momentsPass,
                    p.moments == 4 ? MomentsFormat{GL_RGBA32F, "encodeEvsm4", "visibilityEvsm4"}
                                   : MomentsFormat{GL_RG32F, "encodeEvsm2", "visibilityEvsm2"},
                    glm::vec4(p.positiveExponent, p.negativeExponent, p.minVariance, p.bleedReduction));
  }
};

}  // namespace

TESTBED_REGISTER_TECHNIQUE(ExponentialVarianceShadowMap);

}  // namespace testbed
