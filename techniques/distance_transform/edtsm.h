#pragma once
// Euclidean distance transform shadow mapping (Macedo & Apolinário, GI 2017; EDTSM* from
// their improved anti-aliasing paper, EDTSM*): fixed-size penumbrae from RBSM's anti-aliased hard shadows. Passes, each timed:
//   shadow-map   the shared shadow map
//   rbsm         single-pass SMSR's hard visibility (conservative for edtsm, improved for
//                edtsm-star) and the camera depth into a screen texture
//   edt          the seeds (receivers with an 8-neighbour on the same surface of the other
//                visibility), the exact screen-space feature transform (each pixel's
//                nearest seed) and eq. 8 on the world-space distance to that seed: the
//                transform's row pass tells the seeds, its column pass applies eq. 8 as it
//                finds each nearest seed (edtsm_seeds.comp, edtsm_penumbra.comp), on the
//                rows where eq. 8 can change a pixel only (edtsm_penumbra_band.h)
//   mean-filter  the edge-aware separable mean filter (eqs. 9–10), two dispatches over the
//                tiles where it can change a pixel (edtsm_filter_tiles.h), each invocation
//                four pixels of a line (edtsm_mean_filter.comp)
// With `reference` set, the straightforward pipeline, same output: a full-screen pass per
// step (`seeds`, `edt`, `penumbra`), both filter draws over the whole screen. The paper path
// (path.h) runs that pipeline, the paper's steps, with the EDT banded as the paper's
// (feature_transform_banded.h).
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
// GI 2017: Macedo & Apolinário, "Euclidean Distance Transform Shadow Mapping", Graphics Interface 2017.
#include "techniques/distance_transform/edtsm_filter_tiles.h"
#include "techniques/distance_transform/edtsm_penumbra_band.h"
#include "techniques/distance_transform/feature_transform.h"
#include "techniques/distance_transform/feature_transform_banded.h"
#include "testbed/render/edge_split_pass.h"
#include "testbed/render/revectorization/revectorization_library.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"
#include "testbed/technique/with_parameters.h"

namespace testbed::distance_transform {

// penumbra, filter_width, depth_threshold, max_filter_radius, reference, then RBSM's parameters.
struct EdtsmParameters {
  float penumbra, filterWidth, depthThreshold;
  int maxFilterRadius;
  bool reference;
  revectorization::CommonParameters rbsm;
  void reflect(ParameterBinder& b);
};

class EdtShadowMapping : public WithParameters<EdtsmParameters> {
 public:
  // Both techniques' (declaration.h): `reference` times seeds and penumbra apart.
  static std::vector<PassDeclaration> declaredPasses();
  static std::vector<ResourceDeclaration> declaredResources();

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) override;
  std::vector<std::pair<std::string, ImageF>> debugImages() const override { return rbsm_.debugImages(); }

 protected:
  explicit EdtShadowMapping(bool improved) : improved_(improved) {}

 private:
  void configured() override;
  void allocate(glm::ivec2 size, bool straightforward);
  // Receivers, camera depth and the edge-awareness threshold of edtsm_screen.glsl.
  void bindScreenInputs(const Program& program, const FrameInputs& in) const;
  // The mean filter's uniforms; its input is bound at kEdtsmInputTextureUnit.
  void bindFilter(const Program& program, const FrameInputs& in) const;
  // What follows the seeds: the straightforward passes, or the fused, tiled ones.
  void renderReference(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out, bool bandedEdt);
  void renderFused(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out);

  bool improved_;
  revectorization::Common rbsm_;
  ShadowMapPass shadowMap_;
  ScreenPass screen_;
  FeatureTransformPass featureTransform_;
  BandedFeatureTransformPass bandedTransform_;  // the paper path's
  FilterTiles filterTiles_;
  PenumbraBand band_;
  EdgeSplitPass rbsmPass_{"techniques/distance_transform/edtsm_rbsm.frag"};
  Program seedsProgram_, penumbraProgram_, filterProgram_;  // the reference pipeline
  Program seedRows_, penumbraColumns_, filterRows_, filterColumns_;
  RenderTarget hard_, seeds_, intensity_, filtered_;
};

}  // namespace testbed::distance_transform
