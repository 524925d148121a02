#include "testbed/render/receiver_inputs.h"

#include <glm/gtc/constants.hpp>

#include "testbed/glsl/units.h"
#include "testbed/render/gbuffer_pass.h"
#include "testbed/technique/technique.h"

namespace testbed {

float lightRadiusUniform(const LightDesc& light) {
  // The ground truth reads a directional light's radius as the sun's angular radius in degrees.
  return light.type == LightType::Directional ? glm::radians(light.radius) : light.radius;
}

void bindLightUniforms(const Program& program, const LightTransforms& light, float radius) {
  program.set("uLightViewProjection", light.viewProjection());
  program.set("uLightView", light.view);
  program.set("uLightProjection", light.projection);
  program.set("uLightViewInverse", glm::inverse(light.view));
  program.set("uLightProjectionInverse", glm::inverse(light.projection));
  program.set("uLightPosition", light.position);
  program.set("uLightDirection", light.direction);
  program.set("uLightOrthographic", light.orthographic ? 1 : 0);
  program.set("uLightNear", light.nearPlane);
  program.set("uLightFar", light.farPlane);
  program.set("uLightFov", light.orthographic ? 0.0f : glm::radians(light.fovDegrees));
  program.set("uLightExtent", light.orthographic ? light.extent : 0.0f);
  program.set("uLightRadius", radius);
}

void bindReceiverInputs(const Program& program, const FrameInputs& in) {
  bindReceiverInputs(program, in, in.light.position);
}

void bindReceiverInputs(const Program& program, const FrameInputs& in, const glm::vec3& lightPosition) {
  glBindTextureUnit(kGPositionTextureUnit, in.gbuffer.position().id());
  glBindTextureUnit(kGNormalTextureUnit, in.gbuffer.normal().id());
  program.set("uGPosition", kGPositionTextureUnit);
  program.set("uGNormal", kGNormalTextureUnit);
  LightTransforms light = in.light;
  light.position = lightPosition;
  bindLightUniforms(program, light, lightRadiusUniform(in.scene.light));
  program.set("uFacingLimit", kFacingLimit);
}

}  // namespace testbed
