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

class Smsr final : public SinglePassTechnique {
 public:
  Smsr() : SinglePassTechnique("techniques/revectorization/smsr.frag", false) {}

  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "smsr";
      i.family = "revectorization";
      i.output = OutputKind::Hard;
      i.citation = "Macedo, Apolinário, Revectorization-Based Shadow Mapping, GI 2016";
      i.summary = "single-pass shadow map silhouette revectorization (hard, light-space traversal)";
      i.parameters = withCommonParameters({visibilityParameter()});
      return i;
    }();
    return info;
  }
  const TechniqueInfo& info() const override { return staticInfo(); }

 private:
  void configureTechnique(const ParameterSet& parameters) override {
    improved_ = parameters.getChoice("visibility") == "improved";
    bothSides_ = improved_;  // the improved function traverses the shadowed side too
  }
  void setTechniqueUniforms(const Program& program) const override { program.set("uImproved", improved_ ? 1 : 0); }
  bool improved_ = false;
};

}  // namespace
}  // namespace testbed::revectorization

namespace testbed {
using revectorization::Smsr;
TESTBED_REGISTER_TECHNIQUE(Smsr);
}  // namespace testbed
