#pragma once
// The base of vsm, esm, evsm and msm: the shared moments and blur passes (MomentsPass),
// then one screen pass (visibility.frag) that samples the filtered moments once per
// receiver. A technique only declares its parameters (its own, then the MomentsPass
// ones) and, in configure(), fills in its MomentsFormat and the four numbers its GLSL
// entry points read.
#include <glm/glm.hpp>

#include "techniques/prefiltered/moments_pass.h"
#include "testbed/render/screen_pass.h"
#include "testbed/technique/technique.h"

namespace testbed {

class PrefilteredTechnique : public ShadowTechnique {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) final;

 protected:
  // Call from configure(): the shared passes' parameters plus the technique's choice.
  void configureShared(const MomentsPass::Parameters& moments, MomentsFormat format, glm::vec4 params);

 private:
  MomentsPass moments_;
  MomentsFormat format_;
  glm::vec4 params_{0.0f};
  ScreenPass screen_;
  Program visibility_;
};

}  // namespace testbed
