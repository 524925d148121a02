// Single-pass SMSR visibility (GI 2016 §3.2) in two variants:
// - conservative (uImproved = 0; EDTSM* eq. 4): only lit texels next to shadow
//   (entering discontinuities) are traversed; a lit sample of an L-shaped step becomes
//   shadow iff 1 − α_x > α_y.
// - improved (uImproved = 1; EDTSM* eq. 7): both sides are traversed and
//   v = 0 iff (1 − s) + (2s − 1)(α_x + α_y) < 0.5.
// α_x, α_y are the normalized distances to the horizontal and vertical ends (EDTSM*
// §3.1), from the traversals along the map's x and y axes. For a texel next to a straight
// stretch of an edge, the traversal across the edge ends at once (L = 1) and its α is the
// sample's sub-texel distance from the edge; along the edge it is the position in the run.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
//
// The 12 configurations of v_SMSR are in the paper's supplementary material, which we do
// not have. Our reading, from the paper's text (§3.2) and EDTSM* §3.1:
// - a straight run (no end found along an axis, e.g. longer than 2·max_search) keeps the
//   shadow test's answer (α = 1 on that axis makes both equations answer s);
// - conservative: a U-shape (both ends found, which includes opposite umbra neighbours)
//   becomes shadow;
// - improved: a U-shape uses the tent α = 2·min(dist)/L so the notch is closed from both
//   ends; being symmetric in s, it also opens thin shadowed notches from both ends.
#include "testbed/render/revectorization/revectorization.glsl"

uniform int uImproved;

// EDTSM* eq. 4 (GI 2016 SMSR): lit side only.
float smsrConservative(RvSample r) {
  if (r.x.kind == RV_U || r.y.kind == RV_U) return 0.0;
  if (r.x.kind == RV_NO_END || r.y.kind == RV_NO_END) return 1.0;
  return 1.0 - r.x.alpha > r.y.alpha ? 0.0 : 1.0;
}

// EDTSM* eq. 7: both sides.
float smsrImproved(RvSample r) {
  return (1.0 - r.s) + (2.0 * r.s - 1.0) * (r.x.alpha + r.y.alpha) < 0.5 ? 0.0 : 1.0;
}

// True, with the visibility v, where the sample's texel is no edge (v = s then).
bool smsrClassify(vec2 uv, float depth, out float v) {
  RvSample r = rvClassify(uv, depth, uImproved == 1);
  v = r.s;
  return !r.edge;
}

// Visibility of a traversed sample (rvSample): 1 lit, 0 shadow.
float smsrOf(RvSample r) {
  if (!r.edge) return r.s;
  return uImproved == 1 ? smsrImproved(r) : smsrConservative(r);
}

// Visibility of the light-space sample (uv, light depth).
float smsrVisibility(vec2 uv, float depth) { return smsrOf(rvSample(uv, depth, uImproved == 1)); }
