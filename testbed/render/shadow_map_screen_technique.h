#pragma once
// The shape of the simplest techniques (sm, pcf, the single-pass revectorization family):
// the shared shadow map, then one timed full-screen pass running the technique's own
// fragment shader with the receiver and shadow-map uniforms bound. A subclass names its
// shader and pass, binds its parameters (handing the shadow map its part) and sets its
// own uniforms; the passes, timing and bindings live here once.
#include <string>
#include <utility>

#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"

namespace testbed {

class ShadowMapScreenTechnique : public ShadowTechnique {
 public:
  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) final;

 protected:
  // `fragmentKey`: the embedded shader of the screen pass; `passName`: its timer scope.
  explicit ShadowMapScreenTechnique(std::string fragmentKey, std::string passName = "visibility")
      : fragmentKey_(std::move(fragmentKey)), passName_(std::move(passName)) {}
  // From configure(): the ShadowMapPass::Parameters among the technique's.
  void configureShadowMap(const ShadowMapPass::Parameters& parameters) { shadowMap_.configure(parameters); }
  virtual void setUniforms(const Program& program) const = 0;
  // Runs after the timed passes, outside any timer scope (debug views).
  virtual void afterTimedPasses(const FrameInputs&, const Texture& /*shadowMap*/) {}

 private:
  std::string fragmentKey_, passName_;
  ShadowMapPass shadowMap_;
  ScreenPass screen_;
  Program program_;
};

}  // namespace testbed
