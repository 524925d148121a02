#version 450 core
// smsr-2pass, pass 2 and merge (Bondarev 2014): the screen-space search of
// smsr_2pass_search.glsl, then single-pass SMSR's conservative clipping of the ONDS
// (smsr.glsl, EDTSM* eq. 4): Bondarev's own clipping function is not given in full
// (GI 2016 §4.1 says so), and the conservative one is its single-pass successor. Drawn as
// the family's screen pass (testbed/glsl/screen_pass.glsl): pixels without an entering
// discontinuity in pass 1's map keep their shadow test, the others are searched.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
// Bondarev, "Shadow Map Silhouette Revectorization", poster, I3D 2014.
#include "techniques/revectorization/smsr_2pass_search.glsl"
#include "testbed/render/revectorization/smsr.glsl"

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) {
  RvSample s = twoPassSample(pixel, r);
  return s.edge ? smsrConservative(s) : s.s;
}

bool screenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  vec4 disc = texelFetch(uDiscontinuityMap, pixel, 0);
  v = 1.0 - disc.b;
  return twoPassNoEdge(disc);
}

#include "testbed/glsl/screen_pass.glsl"
