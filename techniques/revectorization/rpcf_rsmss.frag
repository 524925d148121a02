#version 450 core
// Screen pass of `rpcf-rsmss`: the receiver from the G-buffer, its light-space sample, and
// the visibility function of rpcf_rsmss.glsl.
#include "testbed/glsl/receiver.glsl"
#include "techniques/revectorization/rpcf_rsmss.glsl"

layout(location = 0) out float outVisibility;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  // Facing away: shadowed, and no part of the discontinuity computation (GI 2016 §3.2).
  if (facesAwayFromLight(r)) {
    outVisibility = 0.0;
    return;
  }
  vec3 light = lightSpace(r.position);
  outVisibility = rpcfRsmssVisibility(light.xy, light.z);
}
