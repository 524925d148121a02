#version 450 core
// Drawn where the stencil count is 0 (outside every volume): lit, unless the receiver
// faces away from the light or lies outside the light's frustum (the shadow maps' border
// convention: outside reads as shadow).
#include "testbed/glsl/receiver.glsl"

uniform float uWeight;  // 1 for a point light, 1/N per area-light sample
layout(location = 0) out float outVisibility;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  bool inFrustum = insideLightFrustum(lightSpace(r.position));
  outVisibility = (facesAwayFromLight(r) || !inFrustum) ? 0.0 : uWeight;
}
