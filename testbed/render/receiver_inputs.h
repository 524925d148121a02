#pragma once
// Uniforms and texture bindings of glsl/receiver.glsl for a screen pass: the G-buffer on
// texture units 0 and 1, and the light's (glsl/light.glsl).
#include "testbed/gl/objects.h"
#include "testbed/scene/view.h"

namespace testbed {

struct FrameInputs;

void bindReceiverInputs(const Program& program, const FrameInputs& in);
// The same with the light's position replaced (area-light samples).
void bindReceiverInputs(const Program& program, const FrameInputs& in, const glm::vec3& lightPosition);

// glsl/light.glsl's uniforms from the light's transforms and its area radius in the
// shader's units (lightRadiusUniform). Every uniform of light.glsl, once.
void bindLightUniforms(const Program& program, const LightTransforms& light, float radius);
// uLightRadius of a scene's light: the spot's disk radius (world units) as given, the
// directional light's angular radius converted from degrees to radians.
float lightRadiusUniform(const LightDesc& light);

}  // namespace testbed
