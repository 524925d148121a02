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

  static const TechniqueInfo& staticInfo() {
    static const TechniqueInfo info = [] {
      TechniqueInfo i;
      i.id = "rsmss";
      i.family = "revectorization";
      i.output = OutputKind::Filtered;
      i.citation = "Macedo, Apolinário, Revectorization-Based Shadow Mapping, GI 2016";
      i.summary = "revectorization-based silhouette smoothing: continuous visibility over both edge sides";
      i.parameters = withCommonParameters({});
      return i;
    }();
    return info;
  }
  const TechniqueInfo& info() const override { return staticInfo(); }

 private:
  void configureTechnique(const ParameterSet&) override {}
  void setTechniqueUniforms(const Program&) const override {}
};

}  // namespace
}  // namespace testbed::revectorization

namespace testbed {
using revectorization::Rsmss;
TESTBED_REGISTER_TECHNIQUE(Rsmss);
}  // namespace testbed
