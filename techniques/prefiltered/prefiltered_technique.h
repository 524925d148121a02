#pragma once
// The base of vsm, esm, evsm and msm: the shared moments and blur passes (MomentsPass),
// then one screen pass (visibility.frag) that samples the filtered moments once per
// receiver. A technique derives PrefilteredTechnique<P>, declares its parameters (its
// own, then the MomentsPass ones as `moments`) and, in configured(), sets its
// MomentsFormat and the four numbers its GLSL entry points read.
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/prefiltered/moments_pass.h"
#include "testbed/render/screen_pass.h"
#include "testbed/technique/technique.h"
#include "testbed/technique/with_parameters.h"

namespace testbed {

// What vsm, esm, evsm and msm declare (declaration.h): the moments pass, implementing
// `momentsStep`, the blur (the pre-filter every one of their papers has), and the
// visibility, implementing `visibilityStep`; the moments stored as one of `momentFormats`
// (with the depth buffer they are drawn with) and the blur's scratch.
std::vector<PassDeclaration> prefilteredPasses(std::string momentsStep, std::string visibilityStep);
std::vector<ResourceDeclaration> prefilteredResources(const std::vector<GLenum>& momentFormats);

class PrefilteredBase : public ShadowTechnique {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) final;

 protected:
  void configureMoments(const MomentsPass::Parameters& moments);
  // From configured(): the technique's storage and the `params` of its GLSL entry points.
  void setEncoding(MomentsFormat format, glm::vec4 params);

 private:
  MomentsPass moments_;
  MomentsFormat format_;
  glm::vec4 params_{0.0f};
  ScreenPass screen_;
  Program visibility_;
};

// P: the technique's parameter struct, holding the MomentsPass ones as `moments`.
template <class P>
class PrefilteredTechnique : public WithParameters<P, PrefilteredBase> {
 private:
  void configureShared() final { this->configureMoments(this->parameters_.moments); }
};

}  // namespace testbed
