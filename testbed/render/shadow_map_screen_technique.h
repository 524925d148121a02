#pragma once
// The shape of the simplest techniques (sm, pcf, the plugin example): the shared shadow
// map, then one timed full-screen pass running the technique's own fragment shader with
// the receiver and shadow-map uniforms bound. A technique derives
// ShadowMapScreenTechnique<P>, names its shader and pass and sets its own uniforms; the
// passes, timing, bindings and the shadow map's parameters live here once. With a run's
// cascades (FrameInputs::shadowSetup, docs/cascades.md) the map is an array of one layer per
// cascade and the same shader, compiled with TESTBED_CASCADES, reads each receiver's layer
// (glsl/cascades.glsl); with the default set-up it is the one map, as it always was.
#include <string>
#include <utility>
#include <vector>

#include "testbed/render/screen_pass.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/technique/technique.h"
#include "testbed/technique/with_parameters.h"

namespace testbed {

// The passes, independent of the parameter struct (compiled once, in the testbed).
class ShadowMapScreenBase : public ShadowTechnique {
 public:
  // What a technique of this shape declares (declaration.h): the shadow map's pass and map,
  // and its screen pass `passName`, which implements `paperStep`.
  static std::vector<PassDeclaration> declaredPasses(std::string paperStep, std::string passName = "visibility");
  static std::vector<ResourceDeclaration> declaredResources() { return {ShadowMapPass::declaredMap()}; }
  // `passes` and a pass per cascade ("cascade-0" …), for a technique that renders the run's
  // cascades (CascadeSupport in technique.h): its map per cascade, timed apart.
  static std::vector<PassDeclaration> withCascadePasses(std::vector<PassDeclaration> passes);

  void render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) final;
  // The cascades of the last frame (none with the default set-up: the one map of the light).
  std::vector<ShadowMapUse> shadowMaps() const override { return maps_; }

 protected:
  // `fragmentKey`: the embedded shader of the screen pass; `passName`: its timer scope.
  explicit ShadowMapScreenBase(std::string fragmentKey, std::string passName = "visibility")
      : fragmentKey_(std::move(fragmentKey)), passName_(std::move(passName)) {}
  // The technique's polygon offset; each frame applies what the run's bias mode keeps of it
  // (ShadowMapPass::appliedOffset).
  void configureShadowMap(const ShadowMapPass::Parameters& parameters) { offset_ = parameters; }
  // The technique's own uniforms of the screen pass, set before each draw. `in` is the
  // frame's (its light, camera, scene, sizes): what a technique needs per frame comes
  // from here, so none copies render()'s body. The receiver's, the light's
  // (glsl/light.glsl) and the shadow map's uniforms are already set.
  virtual void setUniforms(const Program& program, const FrameInputs& in) const = 0;
  // Runs after the timed passes, outside any timer scope (debug views).
  virtual void afterTimedPasses(const FrameInputs&, const Texture& /*shadowMap*/) {}

 private:
  // The set-up's maps into the array's layers, bound with glsl/cascades.glsl's uniforms.
  void renderCascades(const FrameInputs& in, PassTimer& timer);
  void bindCascades(const Program& program, const FrameInputs& in) const;
  // glsl/bias.glsl's uniforms, where the technique's shader reads them (shadowLookup).
  static void bindBias(const Program& program, const ShadowSetup& setup);

  std::string fragmentKey_, passName_;
  ShadowMapPass shadowMap_;
  ShadowMapPass::Parameters offset_{};
  ScreenPass screen_;
  Program program_, cascadeProgram_;  // cascadeProgram_: compiled with TESTBED_CASCADES
  std::vector<ShadowMapUse> maps_;
};

// P: the technique's parameter struct, holding the shadow map's as `shadowMap`.
template <class P>
class ShadowMapScreenTechnique : public WithParameters<P, ShadowMapScreenBase> {
 protected:
  using WithParameters<P, ShadowMapScreenBase>::WithParameters;

 private:
  void configureShared() final { this->configureShadowMap(this->parameters_.shadowMap); }
};

}  // namespace testbed
