// `evsm`: exponential variance shadow maps (Lauritzen & McCool 2008): Chebyshev's bound on
// exponentially warped depth, positive warp exp(c⁺·z) and negative −exp(−c⁻·z) with z
// mapped to [−1, 1]; with four moments the smaller of the two bounds.
#include "techniques/prefiltered/prefiltered_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

class ExponentialVarianceShadowMap final : public PrefilteredTechnique {
 public:
  static const TechniqueInfo& staticInfo() {
    // 32-bit floats as in the paper. The second moment exp(2c) must fit a float with room
    // for the variance plus (t − μ)² of Chebyshev's denominator: c ≤ 42 (exp(84) ≈ 3e36).
    static const TechniqueInfo info = familyInfo(
        "evsm", "Lauritzen & McCool, Layered variance shadow maps, GI 2008",
        "exponential variance shadow maps: Chebyshev on exp-warped depth, 32-bit float",
        {ParameterSpec::real("positive_exponent", 40.0, 1.0, 42.0, "c+ of the warp exp(c+ z), z in [-1, 1]"),
         ParameterSpec::real("negative_exponent", 5.0, 1.0, 42.0, "c- of the warp -exp(-c- z), z in [-1, 1]"),
         ParameterSpec::choice("moments", "4", {"2", "4"},
                               "2: positive warp only (RG32F); 4: both warps, min of the bounds (RGBA32F)"),
         ParameterSpec::real("min_variance", 1e-6, 0.0, 1e-3,  // as vsm's, see vsm.cpp
                             "variance floor in normalized linear depth, scaled by each warp's slope"),
         ParameterSpec::real("bleed_reduction", 0.0, 0.0, 0.99,
                             "light-bleeding reduction: linstep(amount, 1, p_max); 0 = none")});
    return info;
  }
  const TechniqueInfo& info() const override { return staticInfo(); }

  void configure(const ParameterSet& p) override {
    const bool four = p.getChoice("moments") == "4";
    configureShared(p,
                    four ? MomentsFormat{GL_RGBA32F, "encodeEvsm4", "visibilityEvsm4"}
                         : MomentsFormat{GL_RG32F, "encodeEvsm2", "visibilityEvsm2"},
                    glm::vec4(float(p.getFloat("positive_exponent")), float(p.getFloat("negative_exponent")),
                              float(p.getFloat("min_variance")), float(p.getFloat("bleed_reduction"))));
  }
};

}  // namespace

TESTBED_REGISTER_TECHNIQUE(ExponentialVarianceShadowMap);

}  // namespace testbed
