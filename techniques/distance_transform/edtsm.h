#pragma once
// Euclidean distance transform shadow mapping (Macedo & Apolinário, GI 2017; EDTSM* from
// their improved anti-aliasing paper, EDTSM*): fixed-size penumbrae from RBSM's anti-aliased hard shadows. Passes, each timed:
//   shadow-map   the shared shadow map
//   rbsm         single-pass SMSR's hard visibility (conservative for edtsm, improved for
//                edtsm-star) and the camera depth into a screen texture
//   seeds        receivers with an 8-neighbour on the same surface of the other visibility
//   edt          the exact screen-space feature transform: each pixel's nearest seed
//   penumbra     eq. 8 on the world-space distance to that seed
//   mean-filter  the edge-aware separable mean filter (eqs. 9–10), two draws
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
// GI 2017: Macedo & Apolinário, "Euclidean Distance Transform Shadow Mapping", Graphics Interface 2017.
#include "techniques/distance_transform/feature_transform.h"
#include "techniques/revectorization/revectorization_technique.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"
#include "testbed/technique/with_parameters.h"

namespace testbed::distance_transform {

// penumbra, filter_width, depth_threshold, max_filter_radius, then RBSM's parameters.
struct EdtsmParameters {
  float penumbra, filterWidth, depthThreshold;
  int maxFilterRadius;
  revectorization::CommonParameters rbsm;
  void reflect(ParameterBinder& b);
};

class EdtShadowMapping : public WithParameters<EdtsmParameters> {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override;
  std::vector<std::pair<std::string, ImageF>> debugImages() const override { return rbsm_.debugImages(); }

 protected:
  explicit EdtShadowMapping(bool improved) : improved_(improved) {}

 private:
  void configured() override;
  void allocate(glm::ivec2 size);
  // Receivers, camera depth and the edge-awareness threshold of edtsm_screen.glsl.
  void bindScreenInputs(const Program& program, const FrameInputs& in) const;

  bool improved_;
  revectorization::Common rbsm_;
  ShadowMapPass shadowMap_;
  ScreenPass screen_;
  FeatureTransformPass featureTransform_;
  revectorization::EdgeSplitPass rbsmPass_{"techniques/distance_transform/edtsm_rbsm.frag"};
  Program seedsProgram_, penumbraProgram_, filterProgram_;
  RenderTarget hard_, seeds_, intensity_, filtered_;
};

}  // namespace testbed::distance_transform
