#version 450 core
// The screen pass of every pre-filtered technique: one filtered lookup of the moments at
// the receiver, then MOMENTS_VISIBILITY (moments_format.h).
#include "testbed/glsl/receiver.glsl"
#include "techniques/prefiltered/light_depth.glsl"
#include "techniques/prefiltered/moments.glsl"

uniform sampler2D uMoments;
uniform vec4 uParams;
layout(location = 0) out float outVisibility;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  vec3 light = lightSpace(r.position);
  // Outside the light's frustum is shadow (glsl/receiver.glsl's convention). The moments
  // map is clamped to its edge for filtering, so the map itself cannot say so.
  if (facesAwayFromLight(r) || !insideLightFrustum(light)) {
    outVisibility = 0.0;
    return;
  }
  // In front of the near plane nothing can occlude: depth 0 is lit by every function.
  float t = clamp(lightLinearDepth(r.position), 0.0, 1.0);
  outVisibility = MOMENTS_VISIBILITY(texture(uMoments, light.xy), t, uParams);
}
