// `esm`: exponential shadow maps (Annen et al. 2008): exp(c·z) filtered; visibility
// exp(−c·t)·E[exp(c·z)], clamped to [0, 1].
#include "techniques/prefiltered/prefiltered_technique.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

struct EsmParameters {
  float exponent;
  MomentsPass::Parameters moments;
  void reflect(ParameterBinder& b) {
    // R32F as in the paper. exp(c) at the far plane must stay below FLT_MAX (3.4e38 =
    // exp(88.7)), hence c ≤ 88; the paper's c = 80 gives exp(80) ≈ 5.5e34.
    b.real("exponent", exponent, 80.0, 1.0, 88.0, "c of exp(c z); at most 88 so exp(c) fits a 32-bit float");
    moments.reflect(b);
  }
};

class ExponentialShadowMap final : public PrefilteredTechnique<EsmParameters> {
  void configured() override {
    setEncoding(MomentsFormat{GL_R32F, "encodeEsm", "visibilityEsm"}, glm::vec4(parameters_.exponent, 0, 0, 0));
  }
};

TESTBED_REGISTER_TECHNIQUE(ExponentialShadowMap, .id = "esm", .output = OutputKind::Filtered,
                           .citation = "Annen, Mertens, Seidel, Flerackers & Kautz, Exponential shadow maps, GI 2008",
                           .summary = "exponential shadow maps: exp(c z) in R32F, Gaussian-filtered; exp(-c t) E[exp(c z)]",
                           .passes = prefilteredPasses("exp(c z) of light depth (Annen et al., GI 2008)", "exp(-c t) E[exp(c z)], clamped"),
                           .resources = prefilteredResources({GL_R32F}));

}  // namespace
}  // namespace testbed
