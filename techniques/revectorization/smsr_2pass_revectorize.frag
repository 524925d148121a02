#version 450 core
// smsr-2pass, pass 2 and merge (Bondarev 2014): the screen-space search of
// smsr_2pass_search.glsl, then single-pass SMSR's conservative clipping of the ONDS
// (smsr.glsl, seed 004 eq. 4): Bondarev's own clipping function is not given in full
// (GI 2016 §4.1 says so), and the conservative one is its single-pass successor.
#include "techniques/revectorization/smsr_2pass_search.glsl"
#include "techniques/revectorization/smsr.glsl"

layout(location = 0) out float outVisibility;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  Receiver r;
  if (!loadReceiver(pixel, r)) discard;
  if (facesAwayFromLight(r)) {
    outVisibility = 0.0;
    return;
  }
  RvSample s = twoPassSample(pixel, r);
  outVisibility = s.edge ? smsrConservative(s) : s.s;
}
