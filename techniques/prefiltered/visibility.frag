#version 450 core
// The screen pass of every pre-filtered technique: one filtered lookup of the moments at
// the receiver, then MOMENTS_VISIBILITY (moments_format.h). The moments map is clamped to
// its edge for filtering, so outside the light's frustum only screen_pass.glsl's rule
// says shadow.
#include "testbed/glsl/receiver.glsl"
#include "techniques/prefiltered/light_depth.glsl"
#include "techniques/prefiltered/moments.glsl"

uniform sampler2D uMoments;
uniform vec4 uParams;

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) {
  // In front of the near plane nothing can occlude: depth 0 is lit by every function.
  float t = clamp(lightLinearDepth(r.position), 0.0, 1.0);
  return MOMENTS_VISIBILITY(texture(uMoments, light.xy), t, uParams);
}

#include "testbed/glsl/screen_pass.glsl"
