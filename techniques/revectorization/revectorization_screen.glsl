// The screen pass shared by smsr, rsmss and the RPCF variants, drawn twice (see
// edge_split_pass.h). The including shader defines
//   float rvScreenVisibility(ivec2 pixel, Receiver r, vec3 light)   the technique's
//       visibility of the receiver r at `pixel`, whose light-space sample is `light`
//       (uv, light depth), and
//   bool rvScreenClassify(ivec2 pixel, Receiver r, vec3 light, out float v)   true, with
//       v, where nothing the visibility looks at is an edge,
// and, with RV_SCREEN_OUTPUT defined, its own outputs (else: the visibility target's)
//   void rvScreenWrite(Receiver r, float v)                a receiver's visibility v, and
//   void rvScreenFacingAway(Receiver r)                    a receiver facing away.
// With RV_CLASSIFY defined (first draw) every receiver gets the shadow test's answer where
// that is the technique's answer, and depth 0 marks the others; the second draw runs the
// full visibility on the marked pixels only, which the early depth test finds before the
// shader runs. Only texels on a discontinuity are traversed (GI 2016 §3.2), so most pixels
// never pay for a traversal.
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include "testbed/glsl/receiver.glsl"

#ifndef RV_SCREEN_OUTPUT
layout(location = 0) out float outVisibility;
void rvScreenWrite(Receiver r, float v) { outVisibility = v; }
// Facing away: shadowed, and no part of the discontinuity computation (GI 2016 §3.2).
void rvScreenFacingAway(Receiver r) { outVisibility = 0.0; }
#endif

#ifdef RV_CLASSIFY
void main() {
  Receiver r;
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (!loadReceiver(pixel, r)) discard;
  gl_FragDepth = 1.0;
  if (facesAwayFromLight(r)) {
    rvScreenFacingAway(r);
    return;
  }
  vec3 light = lightSpace(r.position);
  float v;
  if (rvScreenClassify(pixel, r, light, v))
    rvScreenWrite(r, v);
  else
    gl_FragDepth = 0.0;  // an edge: the second draw computes it
}
#else
layout(early_fragment_tests) in;

void main() {
  Receiver r;
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (!loadReceiver(pixel, r)) discard;
  if (facesAwayFromLight(r)) {
    rvScreenFacingAway(r);
    return;
  }
  vec3 light = lightSpace(r.position);
  rvScreenWrite(r, rvScreenVisibility(pixel, r, light));
}
#endif
