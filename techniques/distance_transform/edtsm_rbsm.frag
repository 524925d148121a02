#version 450 core
// EDTSM's rbsm pass: single-pass SMSR's hard visibility (smsr.glsl, conservative or
// improved) and, beside it, the receiver's camera depth (edtsm_screen.glsl's layout).
#include "techniques/distance_transform/edtsm_screen.glsl"
#include "techniques/revectorization/smsr.glsl"

layout(location = 0) out vec2 outHard;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  if (facesAwayFromLight(r)) {
    outHard = vec2(0.0, -1.0);
    return;
  }
  vec3 light = lightSpace(r.position);
  outHard = vec2(smsrVisibility(light.xy, light.z), cameraDepth(r.position));
}
