#pragma once
// The base of vsm, esm, evsm and msm: the shared moments and blur passes (MomentsPass),
// then one screen pass (visibility.frag) that samples the filtered moments once per
// receiver. A technique only declares its parameters and, in configure(), fills in its
// MomentsFormat and the four numbers its GLSL entry points read.
#include <vector>

#include <glm/glm.hpp>

#include "techniques/prefiltered/moments_pass.h"
#include "testbed/render/screen_pass.h"
#include "testbed/technique/technique.h"

namespace testbed {

class PrefilteredTechnique : public ShadowTechnique {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) final;

 protected:
  // TechniqueInfo fields common to the family, with `own` parameters followed by the
  // shared passes' (blur, mips).
  static TechniqueInfo familyInfo(std::string id, std::string citation, std::string summary,
                                  std::vector<ParameterSpec> own);
  // Call from configure(): the shared passes' parameters plus the technique's choice.
  void configureShared(const ParameterSet& parameters, MomentsFormat format, glm::vec4 params);

 private:
  MomentsPass moments_;
  MomentsFormat format_;
  glm::vec4 params_{0.0f};
  ScreenPass screen_;
  Program visibility_;
};

}  // namespace testbed
