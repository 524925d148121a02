#version 450 core
// One direction of the separable Gaussian: 2·BLUR_RADIUS + 1 texels along BLUR_STEP,
// weights uWeights[|offset|] (binomial, see moments_pass.cpp). Clamped to the map's edge;
// what lies outside the map is decided in the screen pass, not here. Radius and direction
// are compile-time constants (separable_blur.cpp builds one program per direction), so the
// loop unrolls into straight fetches: the same sums in the same order as a loop.
//
// BLUR_PACK (separable_blur.h) > 1 packs the intermediate between the two directions:
// BLUR_PACK consecutive texels of a row, 4 / BLUR_PACK channels each (R32F: 4, RG32F: 2),
// in one RGBA32F texel. The row pass (BLUR_STEP (1, 0)) then runs one fragment per
// BLUR_PACK outputs and fetches each of their BLUR_PACK + 2·BLUR_RADIUS source texels
// once; the column pass unpacks. Every sum is the unpacked pass's, on the same float32
// values, so the result is the same bit for bit; what changes is the number of fragments
// and fetches, which is what a software rasterizer spends its time on, not bytes.
uniform sampler2D uSource;
uniform float uWeights[BLUR_RADIUS + 1];
layout(location = 0) out vec4 outMoments;

const ivec2 kStep = BLUR_STEP;

#if BLUR_PACK == 1
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uSource, 0) - 1;
  vec4 sum = uWeights[0] * texelFetch(uSource, texel, 0);
  for (int i = 1; i <= BLUR_RADIUS; ++i) {
    sum += uWeights[i] * (texelFetch(uSource, clamp(texel + i * kStep, ivec2(0), last), 0) +
                          texelFetch(uSource, clamp(texel - i * kStep, ivec2(0), last), 0));
  }
  outMoments = sum;
}
#elif BLUR_PACK == 2 || BLUR_PACK == 4
// Moments texel k (0 .. BLUR_PACK − 1) of a packed texel, in the channels a plain one has.
vec4 unpack(vec4 grouped, int k) {
#if BLUR_PACK == 4
  return vec4(grouped[k], 0.0, 0.0, 0.0);
#else
  return k == 0 ? vec4(grouped.xy, 0.0, 0.0) : vec4(grouped.zw, 0.0, 0.0);
#endif
}

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uSource, 0) - 1;
  if (kStep.x == 1) {
    // Rows: this fragment's outputs are moments texels x0 .. x0 + BLUR_PACK − 1 of its row.
    const int kTaps = BLUR_PACK + 2 * BLUR_RADIUS;
    int x0 = texel.x * BLUR_PACK;
    vec4 taps[kTaps];  // source texel x0 − BLUR_RADIUS + j
    for (int j = 0; j < kTaps; ++j)
      taps[j] = texelFetch(uSource, clamp(ivec2(x0 - BLUR_RADIUS + j, texel.y), ivec2(0), last), 0);
    vec4 grouped = vec4(0.0);
    for (int k = 0; k < BLUR_PACK; ++k) {
      vec4 sum = uWeights[0] * taps[k + BLUR_RADIUS];
      for (int i = 1; i <= BLUR_RADIUS; ++i)
        sum += uWeights[i] * (taps[k + BLUR_RADIUS + i] + taps[k + BLUR_RADIUS - i]);
#if BLUR_PACK == 4
      grouped[k] = sum.x;
#else
      if (k == 0) grouped.xy = sum.xy;
      else grouped.zw = sum.xy;
#endif
    }
    outMoments = grouped;
  } else {
    // Columns: the packed intermediate has the map's height; its texel texel.x / BLUR_PACK.
    ivec2 source = ivec2(texel.x / BLUR_PACK, texel.y);
    int k = texel.x - source.x * BLUR_PACK;
    vec4 sum = uWeights[0] * unpack(texelFetch(uSource, source, 0), k);
    for (int i = 1; i <= BLUR_RADIUS; ++i) {
      sum += uWeights[i] * (unpack(texelFetch(uSource, clamp(source + i * kStep, ivec2(0), last), 0), k) +
                            unpack(texelFetch(uSource, clamp(source - i * kStep, ivec2(0), last), 0), k));
    }
    outMoments = sum;
  }
}
#endif
