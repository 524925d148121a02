// `rsmss`: revectorization-based shadow map silhouette smoothing (Macedo & Apolinário,
// GI 2016 §3.3): entering and exiting discontinuities, a continuous visibility that
// smooths the revectorized edge along its run; see rsmss.glsl.
#include "techniques/revectorization/revectorization_technique.h"
#include "testbed/technique/registry.h"

namespace testbed::revectorization {
namespace {

// The family's parameters only.
class Rsmss final : public SinglePassTechnique<CommonParameters> {
 public:
  Rsmss() : SinglePassTechnique("techniques/revectorization/rsmss.frag", true) {}

 private:
  void setTechniqueUniforms(const Program&, const FrameInputs&) const override {}
};

TESTBED_REGISTER_TECHNIQUE(Rsmss, .id = "rsmss", .output = OutputKind::Filtered,
                           .citation = "Macedo, Apolinário, Revectorization-Based Shadow Mapping, GI 2016",
                           .summary = "revectorization-based silhouette smoothing: continuous visibility over both edge sides",
                           .passes = singlePassPasses("RSMSS, GI 2016 §3.3"),
                           .resources = singlePassResources());

}  // namespace
}  // namespace testbed::revectorization
