#version 450 core
// One direction of the separable Gaussian: 2·BLUR_RADIUS + 1 texels along BLUR_STEP,
// weights uWeights[|offset|] (binomial, see moments_pass.cpp). Clamped to the map's edge;
// what lies outside the map is decided in the screen pass, not here. Radius and direction
// are compile-time constants (moments_pass.cpp builds one program per direction), so the
// loop unrolls into straight fetches: the same sums in the same order as a loop.
uniform sampler2D uSource;
uniform float uWeights[BLUR_RADIUS + 1];
layout(location = 0) out vec4 outMoments;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uSource, 0) - 1;
  vec4 sum = uWeights[0] * texelFetch(uSource, texel, 0);
  for (int i = 1; i <= BLUR_RADIUS; ++i) {
    sum += uWeights[i] * (texelFetch(uSource, clamp(texel + i * BLUR_STEP, ivec2(0), last), 0) +
                          texelFetch(uSource, clamp(texel - i * BLUR_STEP, ivec2(0), last), 0));
  }
  outMoments = sum;
}
