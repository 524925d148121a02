#include "testbed/render/receiver_inputs.h"

#include "testbed/render/gbuffer_pass.h"
#include "testbed/technique/technique.h"

namespace testbed {

void bindReceiverInputs(const Program& program, const FrameInputs& in) {
  bindReceiverInputs(program, in, in.light.position);
}

void bindReceiverInputs(const Program& program, const FrameInputs& in, const glm::vec3& lightPosition) {
  glBindTextureUnit(0, in.gbuffer.position().id());
  glBindTextureUnit(1, in.gbuffer.normal().id());
  program.set("uGPosition", 0);
  program.set("uGNormal", 1);
  program.set("uLightViewProjection", in.light.viewProjection());
  program.set("uLightPosition", lightPosition);
  program.set("uLightDirection", in.light.direction);
  program.set("uLightOrthographic", in.light.orthographic ? 1 : 0);
  program.set("uFacingLimit", kFacingLimit);
}

}  // namespace testbed
