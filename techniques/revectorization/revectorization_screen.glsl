// The screen pass shared by smsr, rsmss and the RPCF variants, drawn twice (see
// edge_split_pass.h). The including shader defines
//   float rvScreenVisibility(vec2 uv, float z)             the technique's visibility, and
//   bool rvScreenClassify(vec2 uv, float z, out float v)   true, with v, where no texel the
//                                                          visibility looks at is an edge.
// With RV_CLASSIFY defined (first draw) every receiver gets the shadow test's answer where
// that is the technique's answer, and depth 0 marks the others; the second draw runs the
// full visibility on the marked pixels only, which the early depth test finds before the
// shader runs. Only texels on a discontinuity are traversed (GI 2016 §3.2), so most pixels
// never pay for a traversal.
#include "testbed/glsl/receiver.glsl"

layout(location = 0) out float outVisibility;

#ifdef RV_CLASSIFY
void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  gl_FragDepth = 1.0;
  // Facing away: shadowed, and no part of the discontinuity computation (GI 2016 §3.2).
  if (facesAwayFromLight(r)) {
    outVisibility = 0.0;
    return;
  }
  vec3 light = lightSpace(r.position);
  float v;
  if (rvScreenClassify(light.xy, light.z, v))
    outVisibility = v;
  else
    gl_FragDepth = 0.0;  // an edge: the second draw computes it
}
#else
layout(early_fragment_tests) in;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  if (facesAwayFromLight(r)) {
    outVisibility = 0.0;
    return;
  }
  vec3 light = lightSpace(r.position);
  outVisibility = rvScreenVisibility(light.xy, light.z);
}
#endif
