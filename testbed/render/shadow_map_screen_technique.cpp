#include "testbed/render/shadow_map_screen_technique.h"

#include "testbed/render/receiver_inputs.h"

namespace testbed {

std::vector<PassDeclaration> ShadowMapScreenBase::declaredPasses(std::string paperStep, std::string passName) {
  return {ShadowMapPass::declaredPass(), {.name = std::move(passName), .paperStep = std::move(paperStep)}};
}

void ShadowMapScreenBase::render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  if (!program_) program_ = Program::graphics("testbed/render/fullscreen.vert", fragmentKey_);
  shadowMap_.render(in, timer);
  {
    auto scope = timer.scope(passName_);
    bindReceiverInputs(program_, in);
    bindShadowMap(program_, shadowMap_.depth());
    setUniforms(program_, in);
    screen_.draw(program_, out.framebuffer, in.size);
  }
  afterTimedPasses(in, shadowMap_.depth());
}

}  // namespace testbed
