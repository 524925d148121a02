#pragma once
// The shape of the simplest techniques (sm, pcf): the shared shadow map, then one
// full-screen pass ("visibility") running the technique's own fragment shader with the
// receiver and shadow-map uniforms bound. A subclass names its shader, reads its own
// parameters and sets its own uniforms; the passes, timing and bindings live here once.
#include <string>

#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"

namespace testbed {

class ShadowMapScreenTechnique : public ShadowTechnique {
 public:
  void configure(const ParameterSet& parameters) final;
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) final;

 protected:
  // `fragmentKey`: the embedded shader of the visibility pass.
  explicit ShadowMapScreenTechnique(std::string fragmentKey) : fragmentKey_(std::move(fragmentKey)) {}
  // The technique's parameters beyond ShadowMapPass::parameters().
  virtual void configureOwn(const ParameterSet& parameters) = 0;
  virtual void setUniforms(const Program& program) const = 0;

 private:
  std::string fragmentKey_;
  ShadowMapPass shadowMap_;
  ScreenPass screen_;
  Program program_;
};

}  // namespace testbed
