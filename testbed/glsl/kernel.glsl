// The k×k kernel of PCF and of both RPCF variants (GI 2016 §3.4): k taps a side (odd),
// centred on the receiver's texel. Each tap moves uv by whole texels and lets the lookup
// pick the texel, so the centre tap is exactly the receiver's own lookup (kernel 1 == the
// unfiltered technique bit for bit, whatever rounding the texture unit applies to
// uv·size) and the others are its neighbours. The forms over the shared shadow map take k
// from uKernel, which the including shader declares (a uniform, or a constant compiled in).
#include "testbed/glsl/shadow_test.glsl"

// The tap (x, y) texels away from uv on a map of `size` texels, |x|, |y| ≤ k/2; the second
// form on the shared shadow map.
vec2 kernelTapUv(vec2 uv, ivec2 size, int x, int y) { return uv + vec2(x, y) * (1.0 / vec2(size)); }
vec2 kernelTapUv(vec2 uv, int x, int y) { return kernelTapUv(uv, uShadowMapSize, x, y); }

// The mean of TAP_EXPRESSION over the K×K taps around UV on a map of SIZE texels, row by
// row (y outer, x inner; this order fixes the rounding of the sum); TAP_EXPRESSION reads
// the tap's uv as `tapUv`. The body of the functions the macros below define.
#define KERNEL_MEAN_BODY(K, SIZE, UV, TAP_EXPRESSION)                                  \
  {                                                                                  \
    int h = (K) / 2;                                                                 \
    float sum = 0.0;                                                                 \
    for (int y = -h; y <= h; ++y)                                                    \
      for (int x = -h; x <= h; ++x) {                                                \
        vec2 tapUv = kernelTapUv(UV, SIZE, x, y);                                    \
        sum += TAP_EXPRESSION;                                                       \
      }                                                                              \
    return sum / float((K) * (K));                                                   \
  }

// Defines `float NAME(vec2 uv, float depth)`: the mean of TAP(tap uv, depth) over the
// uKernel × uKernel taps on the shared shadow map.
#define DEFINE_KERNEL_MEAN(NAME, TAP) \
  float NAME(vec2 uv, float depth) KERNEL_MEAN_BODY(uKernel, uShadowMapSize, uv, TAP(tapUv, depth))

// Defines `float NAME(sampler2D map, int k, vec2 uv, float depth)`: the mean of
// TAP(map, tap uv, depth) over k×k taps on `map`.
#define DEFINE_KERNEL_MEAN_OF_MAP(NAME, TAP)            \
  float NAME(sampler2D map, int k, vec2 uv, float depth) \
      KERNEL_MEAN_BODY(k, textureSize(map, 0), uv, TAP(map, tapUv, depth))

// Defines `float NAME(sampler2DArray maps, int layer, int k, vec2 uv, float depth)`: the
// mean of TAP(maps, layer, tap uv, depth) over k×k taps on a layer (a cascade's map).
#define DEFINE_KERNEL_MEAN_OF_LAYER(NAME, TAP)                              \
  float NAME(sampler2DArray maps, int layer, int k, vec2 uv, float depth) \
      KERNEL_MEAN_BODY(k, textureSize(maps, 0).xy, uv, TAP(maps, layer, tapUv, depth))
