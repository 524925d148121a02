#version 450 core
// One direction of the separable Gaussian: 2·BLUR_RADIUS + 1 texels along BLUR_STEP,
// weights uWeights[|offset|] (binomial, see moments_pass.cpp). Clamped to the map's edge;
// what lies outside the map is decided in the screen pass, not here. Radius and direction
// are compile-time constants (separable_blur.cpp builds one program per direction), so the
// loop unrolls into straight fetches: the same sums in the same order as a loop.
//
// The row pass may run one fragment per several outputs (separable_blur.h), fetching each
// of their outputs + 2·BLUR_RADIUS source texels once; every sum is the plain pass's, on
// the same values; what changes is the number of fragments and fetches, which is what a
// software rasterizer spends its time on, not bytes. The sums are `precise`: the GLSL 4.50
// specification then requires their operations in the order written, with no fused
// multiply-add, and single-precision + and × are correctly rounded, so the packed and the
// plain programs give the same bits on any conforming implementation, not only on the
// compiler that happens to fuse them alike (NVIDIA's did not, at kernel 17).
//  BLUR_PACK > 1 (R32F: 4, RG32F: 2): BLUR_PACK consecutive texels of a row, 4 / BLUR_PACK
//    channels each, in one RGBA32F texel of the intermediate; the column pass unpacks.
//  BLUR_LAYERS > 1 (RGBA32F, RGBA16: no spare channels): the outputs go to as many colour
//    attachments, the layers of an array texture of the moments' own format (texel x in
//    layer x % BLUR_LAYERS, column x / BLUR_LAYERS), so each is stored, and for RGBA16
//    rounded, exactly as the plain intermediate stores it; the column pass reads its
//    texel's layer.
uniform float uWeights[BLUR_RADIUS + 1];
const ivec2 kStep = BLUR_STEP;
const int kRowOutputs = BLUR_PACK * BLUR_LAYERS;  // one of the two is 1

#if BLUR_LAYERS > 1 && BLUR_STEP_COLUMNS
uniform sampler2DArray uSource;
#else
uniform sampler2D uSource;
#endif

#if !(BLUR_LAYERS > 1 && BLUR_STEP_COLUMNS)
// The row pass's sums for moments texels x0 .. x0 + kRowOutputs − 1 of row y, each in the
// plain pass's order.
void rowSums(int x0, int y, out vec4 sums[kRowOutputs]) {
  const int kTaps = kRowOutputs + 2 * BLUR_RADIUS;
  ivec2 last = textureSize(uSource, 0) - 1;
  vec4 taps[kTaps];  // source texel x0 − BLUR_RADIUS + j
  for (int j = 0; j < kTaps; ++j) taps[j] = texelFetch(uSource, clamp(ivec2(x0 - BLUR_RADIUS + j, y), ivec2(0), last), 0);
  for (int k = 0; k < kRowOutputs; ++k) {
    precise vec4 sum = uWeights[0] * taps[k + BLUR_RADIUS];
    for (int i = 1; i <= BLUR_RADIUS; ++i)
      sum += uWeights[i] * (taps[k + BLUR_RADIUS + i] + taps[k + BLUR_RADIUS - i]);
    sums[k] = sum;
  }
}
#endif

#if BLUR_LAYERS > 1
#if BLUR_STEP_COLUMNS
layout(location = 0) out vec4 outMoments;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  int lastRow = textureSize(uSource, 0).y - 1;
  ivec3 source = ivec3(texel.x / BLUR_LAYERS, texel.y, texel.x % BLUR_LAYERS);
  precise vec4 sum = uWeights[0] * texelFetch(uSource, source, 0);
  for (int i = 1; i <= BLUR_RADIUS; ++i) {
    sum += uWeights[i] * (texelFetch(uSource, ivec3(source.x, min(source.y + i, lastRow), source.z), 0) +
                          texelFetch(uSource, ivec3(source.x, max(source.y - i, 0), source.z), 0));
  }
  outMoments = sum;
}
#else
layout(location = 0) out vec4 outLayers[BLUR_LAYERS];
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  vec4 sums[kRowOutputs];
  rowSums(texel.x * BLUR_LAYERS, texel.y, sums);
  for (int k = 0; k < BLUR_LAYERS; ++k) outLayers[k] = sums[k];
}
#endif
#else
layout(location = 0) out vec4 outMoments;

#if BLUR_PACK == 1
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uSource, 0) - 1;
  precise vec4 sum = uWeights[0] * texelFetch(uSource, texel, 0);
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
    vec4 sums[kRowOutputs];
    rowSums(texel.x * BLUR_PACK, texel.y, sums);
    vec4 grouped = vec4(0.0);
    for (int k = 0; k < BLUR_PACK; ++k) {
#if BLUR_PACK == 4
      grouped[k] = sums[k].x;
#else
      if (k == 0) grouped.xy = sums[k].xy;
      else grouped.zw = sums[k].xy;
#endif
    }
    outMoments = grouped;
  } else {
    // Columns: the packed intermediate has the map's height; its texel texel.x / BLUR_PACK.
    ivec2 source = ivec2(texel.x / BLUR_PACK, texel.y);
    int k = texel.x - source.x * BLUR_PACK;
    precise vec4 sum = uWeights[0] * unpack(texelFetch(uSource, source, 0), k);
    for (int i = 1; i <= BLUR_RADIUS; ++i) {
      sum += uWeights[i] * (unpack(texelFetch(uSource, clamp(source + i * kStep, ivec2(0), last), 0), k) +
                            unpack(texelFetch(uSource, clamp(source - i * kStep, ivec2(0), last), 0), k));
    }
    outMoments = sum;
  }
}
#endif
#endif
