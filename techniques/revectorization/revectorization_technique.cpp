#include "techniques/revectorization/revectorization_technique.h"

#include <algorithm>

#include "testbed/render/receiver_inputs.h"

namespace testbed::revectorization {

void reflectKernel(ParameterBinder& b, int& kernel) {
  // Odd so the block is centred on the receiver's texel.
  b.integer("kernel", kernel, 3, 1, 31, "filter width k in texels (k×k revectorized taps, odd)").oddOnly();
}

std::vector<PassDeclaration> singlePassPasses(std::string paperStep) {
  return {ShadowMapPass::declaredPass(), DepthImage::declaredPass(), EdgeSplitPass::classifyingDraw("classify"),
          {.name = "revectorize", .paperStep = std::move(paperStep)}};
}

std::vector<ResourceDeclaration> singlePassResources(DepthImage::Layout fastLayout) {
  return {ShadowMapPass::declaredMap(), DepthImage::declared(fastLayout), EdgeSplitPass::declaredMarks(),
          Common::declaredDebugView()};
}

void SinglePassBase::configureCommon(const CommonParameters& parameters) {
  shadowMap_.configure(parameters.shadowMap);
  common_.configure(parameters);
}

void SinglePassBase::render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  shadowMap_.render(in, timer);
  common_.setPath(in.path, depthLayout());
  const bool fast = in.path == TechniquePath::Fast;
  if (fast) {
    renderFastInputs(in, shadowMap_.depth(), timer);
    common_.updateDepthImage(shadowMap_.depth(), timer);
  }
  const auto bind = [&](const Program& program) {
    bindReceiverInputs(program, in);
    common_.bindLibrary(program, shadowMap_.depth());
    setTechniqueUniforms(program, in);
    if (fast) bindFastInputs(program, in);
  };
  screen_.setDefines(shaderDefines() + common_.libraryDefines());
  screen_.draw(in, out, timer, bind, "classify", "revectorize");
  // Untimed: the debug view never changes the timed passes.
  common_.renderDebug(in, shadowMap_.depth(), bothSides_);
}

}  // namespace testbed::revectorization
