#include "testbed/render/shadow_map_screen_technique.h"

#include <algorithm>
#include <string>

#include "testbed/glsl/units.h"
#include "testbed/render/receiver_inputs.h"
#include "testbed/technique/cascades.h"

namespace testbed {

namespace {
std::string cascadePass(int i) { return "cascade-" + std::to_string(i); }
}  // namespace

std::vector<PassDeclaration> ShadowMapScreenBase::declaredPasses(std::string paperStep, std::string passName) {
  return {ShadowMapPass::declaredPass(), {.name = std::move(passName), .paperStep = std::move(paperStep)}};
}

std::vector<PassDeclaration> ShadowMapScreenBase::withCascadePasses(std::vector<PassDeclaration> passes) {
  for (int i = 0; i < kMaxCascades; ++i)
    passes.push_back(ShadowMapPass::declaredPass(
        cascadePass(i), "cascade " + std::to_string(i) + "'s map, fitted to its slice of the view (Zhang et al., "
                        "Parallel-split shadow maps for large-scale virtual environments, VRCIA 2006)"));
  return passes;
}

void ShadowMapScreenBase::renderCascades(const FrameInputs& in, PassTimer& timer) {
  const std::vector<CascadeMap> cascades = fitCascades(in.shadowSetup, in.light, in.fitCamera, in.aspect(),
                                                       in.sceneBounds, in.shadowMapSize);
  shadowMap_.setLayers(int(cascades.size()));
  maps_.clear();
  for (std::size_t i = 0; i < cascades.size(); ++i) {
    shadowMap_.render(in, cascades[i].light, cascadePass(int(i)), timer, int(i));
    maps_.push_back({.light = cascades[i].light, .split = cascades[i].split});
  }
}

void ShadowMapScreenBase::bindCascades(const Program& program, const FrameInputs& in) const {
  std::vector<float> matrices(kMaxCascades * 16, 0.0f), splitFar(kMaxCascades, 0.0f), splitNear(kMaxCascades, 0.0f);
  std::vector<float> scales(kMaxCascades * 4, 0.0f);
  for (std::size_t i = 0; i < maps_.size(); ++i) {
    const glm::mat4 m = maps_[i].light.viewProjection();
    std::copy_n(&m[0][0], 16, matrices.begin() + std::ptrdiff_t(i * 16));
    splitNear[i] = float((*maps_[i].split)[0]);
    splitFar[i] = float((*maps_[i].split)[1]);
    const glm::mat4& p = maps_[i].light.projection;  // the terms texelWorldSize() reads
    const float terms[4] = {p[0][0], p[1][1], p[2][3], p[3][3]};
    std::copy_n(terms, 4, scales.begin() + std::ptrdiff_t(i * 4));
  }
  program.set("uCascadeProjectionScale", scales);
  bindMap(program, "uShadowMaps", kShadowMapTextureUnit, shadowMap_.depth());
  program.set("uShadowMapSize", glm::ivec2(in.shadowMapSize));
  program.set("uCascadeCount", int(maps_.size()));
  program.set("uCascadeMatrices", matrices);
  program.set("uCascadeSplitFar", splitFar);
  program.set("uCascadeSplitNear", splitNear);
  program.set("uCascadeBlendBand", float(in.shadowSetup.blendBand));
  program.set("uCascadeEye", in.fitCamera.eye);
  program.set("uCascadeForward", glm::normalize(in.fitCamera.target - in.fitCamera.eye));
}

void ShadowMapScreenBase::bindBias(const Program& program, const ShadowSetup& setup) {
  if (program.location("uBiasMode") < 0) return;  // a shader without the shared lookup
  program.set("uBiasMode", int(setup.bias));
  program.set("uNormalOffset", float(setup.normalOffset));
  program.set("uReceiverPlaneBias", float(setup.receiverPlaneSteps) * kDepthStep16);
}

void ShadowMapScreenBase::render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  // The default set-up takes the path it always took, so its images do not change by a bit.
  const bool cascades = !in.shadowSetup.single();
  Program& program = cascades ? cascadeProgram_ : program_;
  if (!program)
    program = Program::graphics("testbed/render/fullscreen.vert", fragmentKey_,
                                cascades ? "#define TESTBED_CASCADES\n" : "");
  shadowMap_.configure(ShadowMapPass::appliedOffset(offset_, in.shadowSetup.bias));
  if (cascades) {
    renderCascades(in, timer);
  } else {
    shadowMap_.setLayers(0);
    maps_.clear();
    shadowMap_.render(in, timer);
  }
  {
    auto scope = timer.scope(passName_);
    bindReceiverInputs(program, in);
    if (cascades)
      bindCascades(program, in);
    else
      bindShadowMap(program, shadowMap_.depth());
    bindBias(program, in.shadowSetup);
    setUniforms(program, in);
    screen_.draw(program, out.framebuffer, in.size);
  }
  afterTimedPasses(in, shadowMap_.depth());
}

}  // namespace testbed
