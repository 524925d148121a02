// The one main() of every screen pass (the techniques' visibility passes and the shadow
// volumes' resolve): the receiver at this pixel from the G-buffer (none: discarded), then
// the two rules every technique and ground truth shares, and only then the technique.
//   1. A receiver facing away from the light is shadowed (receiver.glsl).
//   2. A receiver outside the light's frustum, on any side, is shadowed (lightSpace()).
// The including shader defines, before including this file,
//   float screenVisibility(ivec2 pixel, Receiver r, vec3 light)
// the visibility of the receiver r at `pixel` inside the light's frustum, `light` its
// lightSpace() (uv, light depth). With SCREEN_PASS_OUTPUT defined it also defines its own
// outputs (else this file declares the visibility target's):
//   void screenWrite(Receiver r, float v)   a receiver's visibility v, and
//   void screenFacingAway(Receiver r)       a receiver facing away from the light.
//
// A pass may be drawn in two steps (testbed/render/edge_split_pass.h). With
// SCREEN_PASS_CLASSIFY defined (first draw) the shader defines instead
//   bool screenClassify(ivec2 pixel, Receiver r, vec3 light, out float v)
// true, with v, where that cheap answer is the technique's; depth 0 marks the other
// pixels. With SCREEN_PASS_MARKED defined (second draw) screenVisibility runs on the
// marked pixels only, which the early depth test finds before the shader runs.
#include "testbed/glsl/receiver.glsl"
#ifdef TESTBED_CASCADES
#include "testbed/glsl/cascades.glsl"
#endif

#ifndef SCREEN_PASS_OUTPUT
layout(location = 0) out float outVisibility;
void screenWrite(Receiver r, float v) { outVisibility = v; }
void screenFacingAway(Receiver r) { outVisibility = 0.0; }
#endif

#ifdef SCREEN_PASS_MARKED
layout(early_fragment_tests) in;
#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  Receiver r;
  if (!loadReceiver(pixel, r)) discard;
#ifdef SCREEN_PASS_CLASSIFY
  gl_FragDepth = 1.0;
#endif
  vec3 light = lightSpace(r.position);
#ifdef TESTBED_CASCADES
  // The receiver's cascade and its coordinates in that map. The frustum rule stays the
  // frame light's: a stable cascade's square may reach beyond it.
  gCascade = cascadeOf(r.position);
  if (insideLightFrustum(light)) light = lightSpace(cascadeViewProjection(gCascade), r.position);
#endif
  if (facesAwayFromLight(r)) {
    screenFacingAway(r);
    return;
  }
  // One screenWrite for both answers below: llvmpipe runs every branch for all lanes, so
  // a write per branch costs its output's work (EDTSM's camera depth) twice.
  float v = 0.0;
  if (insideLightFrustum(light)) {
#ifdef SCREEN_PASS_CLASSIFY
    // Where the cheap answer is not the technique's, the mark sends the pixel to the
    // second draw, which overwrites what this one writes.
    if (!screenClassify(pixel, r, light, v)) gl_FragDepth = 0.0;
#else
    v = screenVisibility(pixel, r, light);
#ifdef TESTBED_CASCADES
    // In a blend band (cascades.glsl cascadeBlendWeight) the next cascade's answer is mixed
    // in linearly, where the receiver lies in that map's square too (a view fit crops each
    // map to its own slice, which the band, before the split, may leave).
    float w = cascadeBlendWeight(r.position, gCascade);
    if (w > 0.0) {
      vec3 next = lightSpace(cascadeViewProjection(gCascade + 1), r.position);
      if (insideLightFrustum(next)) {
        gCascade += 1;
        v = mix(v, screenVisibility(pixel, r, next), w);
      }
    }
#endif
#endif
  }
  screenWrite(r, v);
}
