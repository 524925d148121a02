// `smsr`: single-pass shadow map silhouette revectorization (Macedo & Apolinário, GI 2016
// §3.2). One screen pass finds the lit texels next to shadow, measures their edge in
// light space and clips the oriented normalized discontinuity space with the conservative
// (EDTSM* eq. 4) or improved (EDTSM* eq. 7) visibility function; see smsr.glsl.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/revectorization/revectorization_technique.h"
#include "testbed/technique/registry.h"

namespace testbed::revectorization {
namespace {

struct SmsrParameters {
  bool improved;
  CommonParameters common;
  void reflect(ParameterBinder& b) {
    reflectVisibility(b, improved);
    common.reflect(b);
  }
};

class Smsr final : public WithVisibilityChoice<SinglePassTechnique<SmsrParameters>> {
 public:
  Smsr() : WithVisibilityChoice("techniques/revectorization/smsr.frag", false) {}
};

TESTBED_REGISTER_TECHNIQUE(Smsr, .id = "smsr", .output = OutputKind::Hard,
                           .citation = "Macedo, Apolinário, Revectorization-Based Shadow Mapping, GI 2016",
                           .summary = "single-pass shadow map silhouette revectorization (hard, light-space traversal)",
                           .passes = singlePassPasses("single-pass SMSR, GI 2016 §3.2"),
                           .resources = singlePassResources());

}  // namespace
}  // namespace testbed::revectorization
