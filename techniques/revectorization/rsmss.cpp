// `rsmss`: revectorization-based shadow map silhouette smoothing (Macedo & Apolinário,
// GI 2016 §3.3): entering and exiting discontinuities, a continuous visibility that
// smooths the revectorized edge along its run; see rsmss.glsl.
#include "techniques/revectorization/revectorization_technique.h"
#include "testbed/technique/registry.h"

namespace testbed::revectorization {
namespace {

class Rsmss final : public SinglePassTechnique {
 public:
  Rsmss() : SinglePassTechnique("techniques/revectorization/rsmss.frag", true) {}

  static TechniqueInfo describe() {
    return {.id = "rsmss",
            .output = OutputKind::Filtered,
            .citation = "Macedo, Apolinário, Revectorization-Based Shadow Mapping, GI 2016",
            .summary = "revectorization-based silhouette smoothing: continuous visibility over both edge sides",
            .parameters = declaredParameters<CommonParameters>()};
  }

  void configure(const ParameterSet& values) override {
    CommonParameters common{};
    bindParameters(values, common);
    configureCommon(common);
  }

 private:
  void setTechniqueUniforms(const Program&) const override {}
};

}  // namespace
}  // namespace testbed::revectorization

namespace testbed {
using revectorization::Rsmss;
TESTBED_REGISTER_TECHNIQUE(Rsmss);
}  // namespace testbed
