// RSMSS visibility (GI 2016 §3.3): entering and exiting discontinuities are both
// traversed and the ONDS is turned into a continuous value, a 1-D smoothing filter along
// the edge. With signed normalized distances r_x, r_y (GI 2016 §3.3, our reading):
//   r_x·r_y < 0  → (1 − s) + (2s − 1)·max(r)
//   r_x·r_y = 0  → s
//   otherwise    → clamp((1 − s) + (2s − 1)(r_x + r_y), 0, 1)
// The paper's own 31 comparisons are in its missing supplementary material; our signs:
// r = +α for an L-shaped axis (one end found), r = −tent for a U-shaped axis (both ends),
// r = 0 for a straight run (no end). So straight runs keep s, an L corner ramps from the
// corner (its 0.5 contour is the improved SMSR line, EDTSM* eq. 7), an axis that is a
// U next to an L ramps along the L axis only, and a texel that is a U in both axes (an
// isolated texel) takes the other side's value. On the edge between a lit and a shadowed
// run of an ideal staircase the two sides give the same value, so the result is
// continuous across it.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include "testbed/render/revectorization/revectorization.glsl"

float rsmssSigned(RvAxis a) {
  if (a.kind == RV_NO_END) return 0.0;
  return a.kind == RV_U ? -max(a.alpha, 1e-6) : max(a.alpha, 1e-6);
}

// True, with the visibility v, where the sample's texel is no edge (v = s then).
bool rsmssClassify(vec2 uv, float depth, out float v) {
  RvSample r = rvClassify(uv, depth, true);
  v = r.s;
  return !r.edge;
}

// Visibility in [0,1] of a traversed sample (rvSample, both sides).
float rsmssOf(RvSample r) {
  if (!r.edge) return r.s;
  float rx = rsmssSigned(r.x), ry = rsmssSigned(r.y);
  float sign = 2.0 * r.s - 1.0;
  if (rx * ry < 0.0) return (1.0 - r.s) + sign * max(rx, ry);
  if (rx * ry == 0.0) return r.s;
  return clamp((1.0 - r.s) + sign * (rx + ry), 0.0, 1.0);
}

// Visibility in [0,1] of the light-space sample (uv, light depth).
float rsmssVisibility(vec2 uv, float depth) { return rsmssOf(rvSample(uv, depth, true)); }
