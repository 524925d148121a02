// The k×k kernel of PCF and of both RPCF variants (GI 2016 §3.4): k = uKernel (odd) taps a
// side, centred on the receiver's texel. Each tap moves uv by whole texels and lets the
// lookup pick the texel, so the centre tap is exactly the receiver's own lookup (kernel 1
// == the unfiltered technique bit for bit, whatever rounding the texture unit applies to
// uv·size) and the others are its neighbours. The including shader declares uKernel (a
// uniform, or a constant compiled in).
#include "testbed/glsl/shadow_test.glsl"

// The tap (x, y) texels away from uv, |x|, |y| ≤ k/2.
vec2 kernelTapUv(vec2 uv, int x, int y) { return uv + vec2(x, y) * (1.0 / vec2(uShadowMapSize)); }

// Defines `float NAME(vec2 uv, float depth)`: the mean of TAP(tap uv, depth) over the k×k
// taps, row by row (y outer, x inner; this order fixes the rounding of the sum).
#define DEFINE_KERNEL_MEAN(NAME, TAP)                                                 \
  float NAME(vec2 uv, float depth) {                                                 \
    int h = uKernel / 2;                                                             \
    float sum = 0.0;                                                                 \
    for (int y = -h; y <= h; ++y)                                                    \
      for (int x = -h; x <= h; ++x) sum += TAP(kernelTapUv(uv, x, y), depth);        \
    return sum / float(uKernel * uKernel);                                           \
  }
