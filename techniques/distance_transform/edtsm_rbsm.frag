#version 450 core
// EDTSM's rbsm pass: single-pass SMSR's hard visibility (smsr.glsl, conservative or
// improved) and, beside it, the receiver's camera depth (edtsm_screen.glsl's layout).
// Drawn as the revectorization family's screen pass is (revectorization_screen.glsl):
// a classifying draw, then the edge pixels only.
#include "techniques/distance_transform/edtsm_screen.glsl"
#include "techniques/revectorization/smsr.glsl"

layout(location = 0) out vec2 outHard;

float rvScreenVisibility(ivec2 pixel, Receiver r, vec3 light) { return smsrVisibility(light.xy, light.z); }
bool rvScreenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  return smsrClassify(light.xy, light.z, v);
}
void rvScreenWrite(Receiver r, float v) { outHard = vec2(v, cameraDepth(r.position)); }
void rvScreenFacingAway(Receiver r) { outHard = vec2(0.0, -1.0); }

#define RV_SCREEN_OUTPUT 1
#include "techniques/revectorization/revectorization_screen.glsl"
