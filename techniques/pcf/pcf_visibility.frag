#version 450 core
#define TESTBED_BIAS_MODES  // the shared set-up's bias modes (testbed/glsl/bias.glsl)
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"
#include "testbed/glsl/kernel.glsl"

uniform float uBias;
uniform int uKernel;    // odd, 1..31
uniform int uBilinear;  // 0: box of nearest tests, 1: bilinear-weighted taps

// k×k nearest tests centred on the texel holding `uv` (testbed/glsl/kernel.glsl).
float boxTap(vec2 uv, float depth) { return shadowTest(uv, depth, uBias); }
DEFINE_KERNEL_MEAN(boxPcf, boxTap)

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

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) {
  vec3 lookup = shadowLookup(r, light);
  return uBilinear == 1 ? bilinearPcf(lookup.xy, lookup.z) : boxPcf(lookup.xy, lookup.z);
}

#include "testbed/glsl/screen_pass.glsl"
