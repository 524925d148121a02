#include "techniques/prefiltered/prefiltered_technique.h"

#include "testbed/render/receiver_inputs.h"

namespace testbed {

void PrefilteredBase::configureMoments(const MomentsPass::Parameters& moments) { moments_.configure(moments); }

void PrefilteredBase::setEncoding(MomentsFormat format, glm::vec4 params) {
  format_ = std::move(format);
  params_ = params;
  visibility_ = Program();  // recompiled for this format on the next render
}

void PrefilteredBase::render(const FrameInputs& in, PassTimer& timer, const VisibilityTarget& out) {
  if (!visibility_)
    visibility_ = Program::graphics("testbed/render/fullscreen.vert", "techniques/prefiltered/visibility.frag",
                                    format_.defines());
  moments_.render(in, timer, format_, params_);

  auto scope = timer.scope("visibility");
  bindReceiverInputs(visibility_, in);
  glBindTextureUnit(2, moments_.moments().id());
  visibility_.set("uMoments", 2);
  visibility_.set("uParams", params_);
  screen_.draw(visibility_, out.framebuffer, in.size);
}

}  // namespace testbed
