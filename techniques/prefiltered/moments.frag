#version 450 core
// The moments pass: MOMENTS_ENCODE (moments_format.h) of the fragment's light depth.
#include "techniques/prefiltered/moments.glsl"
layout(location = 0) in float vLightDepth;
uniform vec4 uParams;
layout(location = 0) out vec4 outMoments;
void main() {
  // Clipping keeps the depth in [0, 1] up to interpolation rounding; the warps want it exact.
  outMoments = MOMENTS_ENCODE(clamp(vLightDepth, 0.0, 1.0), uParams);
}
