#pragma once
// Uniforms and texture bindings of glsl/receiver.glsl for a screen pass: the G-buffer on
// texture units 0 and 1, the light's transforms.
#include "testbed/gl/objects.h"
#include "testbed/scene/view.h"

namespace testbed {

struct FrameInputs;

void bindReceiverInputs(const Program& program, const FrameInputs& in);
// The same with the light's position replaced (area-light samples).
void bindReceiverInputs(const Program& program, const FrameInputs& in, const glm::vec3& lightPosition);

}  // namespace testbed
