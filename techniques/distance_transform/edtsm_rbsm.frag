#version 450 core
// EDTSM's rbsm pass: single-pass SMSR's hard visibility (smsr.glsl, conservative or
// improved) and, beside it, the receiver's camera depth (edtsm_screen.glsl's layout).
// Drawn as the revectorization family's screen pass is (testbed/glsl/screen_pass.glsl):
// a classifying draw, then the edge pixels only.
#include "techniques/distance_transform/edtsm_screen.glsl"
#include "testbed/render/revectorization/smsr.glsl"

layout(location = 0) out vec2 outHard;

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) { return smsrVisibility(light.xy, light.z); }
bool screenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  return smsrClassify(light.xy, light.z, v);
}
void screenWrite(Receiver r, float v) { outHard = vec2(v, cameraDepth(r.position)); }
void screenFacingAway(Receiver r) { outHard = vec2(0.0, -1.0); }

#define SCREEN_PASS_OUTPUT 1
#include "testbed/glsl/screen_pass.glsl"
