#version 450 core
// One direction of the separable Gaussian: 2·uRadius + 1 texels along uStep, weights
// uWeights[|offset|] (binomial, see moments_pass.cpp). Clamped to the map's edge; what lies
// outside the map is decided in the screen pass, not here.
uniform sampler2D uSource;
uniform ivec2 uStep;
uniform int uRadius;
uniform float uWeights[8];
layout(location = 0) out vec4 outMoments;
void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(uSource, 0) - 1;
  vec4 sum = uWeights[0] * texelFetch(uSource, texel, 0);
  for (int i = 1; i <= uRadius; ++i) {
    sum += uWeights[i] * (texelFetch(uSource, clamp(texel + i * uStep, ivec2(0), last), 0) +
                          texelFetch(uSource, clamp(texel - i * uStep, ivec2(0), last), 0));
  }
  outMoments = sum;
}
