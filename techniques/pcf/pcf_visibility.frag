#version 450 core
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"

uniform float uBias;
uniform int uKernel;    // odd, 1..17
uniform int uBilinear;  // 0: box of nearest tests, 1: bilinear-weighted taps
layout(location = 0) out float outVisibility;

// k×k nearest tests centred on the texel holding `uv`. Each tap moves uv by whole texels
// and lets the sampler pick the texel, so the centre tap is exactly sm's lookup (kernel 1
// == sm bit for bit, whatever rounding the texture unit applies to uv·size) and the others
// are its neighbours.
float boxPcf(vec2 uv, float depth) {
  int h = uKernel / 2;
  vec2 texel = 1.0 / vec2(uShadowMapSize);
  float lit = 0.0;
  for (int y = -h; y <= h; ++y)
    for (int x = -h; x <= h; ++x) lit += shadowTest(uv + vec2(x, y) * texel, depth, uBias);
  return lit / float(uKernel * uKernel);
}

// The k×k taps each bilinearly interpolate the tests of their 4 nearest texels. Summed,
// that is (k+1)×(k+1) tests with separable weights: the first row/column weighs 1 − f,
// the last f, the inner ones 1 (f = the fraction past the texel centre to the lower left).
float bilinearPcf(vec2 uv, float depth) {
  int h = uKernel / 2;
  vec2 t = uv * vec2(uShadowMapSize) - 0.5;
  vec2 lowerLeft = floor(t);
  vec2 f = t - lowerLeft;
  ivec2 base = ivec2(lowerLeft);
  float lit = 0.0;
  for (int y = -h; y <= h + 1; ++y) {
    float wy = y == -h ? 1.0 - f.y : (y == h + 1 ? f.y : 1.0);
    for (int x = -h; x <= h + 1; ++x) {
      float wx = x == -h ? 1.0 - f.x : (x == h + 1 ? f.x : 1.0);
      lit += wx * wy * shadowTestTexel(base + ivec2(x, y), depth, uBias);
    }
  }
  // The weights sum to k² only up to rounding: keep the result in [0, 1].
  return clamp(lit / float(uKernel * uKernel), 0.0, 1.0);
}

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  if (facesAwayFromLight(r)) {
    outVisibility = 0.0;
    return;
  }
  vec3 light = lightSpace(r.position);
  outVisibility = uBilinear == 1 ? bilinearPcf(light.xy, light.z) : boxPcf(light.xy, light.z);
}
