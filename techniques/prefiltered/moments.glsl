// Moment encodings and visibility functions of the pre-filtered shadow maps: VSM, ESM,
// EVSM and MSM. Pure functions of their arguments (no uniforms), so the tests evaluate this
// very code on known inputs (moments_probe.frag). Depths z (occluders) and t (receiver)
// are the light's linear depth in [0, 1] (light_depth.glsl).
//
// Each technique is one pair of entry points with a common signature, named by its
// MomentsFormat (moments_format.h) and reached through MOMENTS_ENCODE/MOMENTS_VISIBILITY:
//   vec4  encodeX(float z, vec4 p)                  the moments pass's texel for depth z
//   float visibilityX(vec4 filtered, float t, vec4 p)  1 lit .. 0 shadow
// `p` carries the technique's parameters; its layout is documented per technique below.

// --- Chebyshev's one-tailed inequality (VSM, EVSM) --------------------------------------

// Donnelly & Lauritzen 2006: P(z >= t) <= p_max = σ² / (σ² + (t − μ)²) for t > μ, else 1.
// The variance is floored at minVariance against precision loss in E[z²] − E[z]².
float chebyshevUpperBound(vec2 moments, float t, float minVariance) {
  if (t <= moments.x) return 1.0;
  float variance = max(moments.y - moments.x * moments.x, minVariance);
  float d = t - moments.x;
  return variance / (variance + d * d);
}

// Light-bleeding reduction (Lauritzen, GPU Gems 3 ch. 8): linstep(amount, 1, p_max) cuts
// the tail of the bound; amount 0 leaves it as is. amount < 1 (the parameter's range).
float reduceLightBleeding(float pMax, float amount) {
  return clamp((pMax - amount) / (1.0 - amount), 0.0, 1.0);
}

// VSM. p = (min_variance, bleed_reduction, -, -).
vec4 encodeVsm(float z, vec4 p) { return vec4(z, z * z, 0.0, 0.0); }
float visibilityVsm(vec4 m, float t, vec4 p) {
  return reduceLightBleeding(chebyshevUpperBound(m.xy, t, p.x), p.y);
}

// --- ESM (Annen et al. 2008) ------------------------------------------------------------

float esmWarp(float z, float c) { return exp(c * z); }

// visibility = exp(−c·t) · E[exp(c·z)], evaluated as exp(log E − c·t): exp(−c·t) alone
// underflows to a denormal for c·t > 87 while the product is ~1 on lit surfaces.
float esmVisibility(float filtered, float t, float c) {
  return clamp(exp(log(filtered) - c * t), 0.0, 1.0);
}

// ESM. p = (c, -, -, -).
vec4 encodeEsm(float z, vec4 p) { return vec4(esmWarp(z, p.x), 0.0, 0.0, 0.0); }
float visibilityEsm(vec4 m, float t, vec4 p) { return esmVisibility(m.x, t, p.x); }

// --- EVSM (Lauritzen & McCool 2008) -----------------------------------------------------

// Depth is first mapped from [0, 1] to [−1, 1] (common practice: it centres the two warps
// so each uses the full float range), then warped by exp(c⁺·z) and −exp(−c⁻·z).
vec2 evsmWarp(float z, vec2 exponents) {
  float w = 2.0 * z - 1.0;
  return vec2(exp(exponents.x * w), -exp(-exponents.y * w));
}

// Chebyshev in a warped space. The depth-space variance floor is carried through the warp's
// slope |dw/dz| = 2·c·|w| at the receiver, so min_variance means the same for every
// exponent; sqrt first so the floor does not overflow (c ≤ 42, min_variance ≤ 1e-3).
float evsmBound(vec2 moments, float warped, float c, float minVariance) {
  float floorStd = sqrt(minVariance) * 2.0 * c * abs(warped);
  return chebyshevUpperBound(moments, warped, floorStd * floorStd);
}

// EVSM, four moments: (w⁺, w⁺², w⁻, w⁻²); visibility the smaller of the two bounds.
// p = (c⁺, c⁻, min_variance, bleed_reduction).
vec4 encodeEvsm4(float z, vec4 p) {
  vec2 w = evsmWarp(z, p.xy);
  return vec4(w.x, w.x * w.x, w.y, w.y * w.y);
}
float visibilityEvsm4(vec4 m, float t, vec4 p) {
  vec2 w = evsmWarp(t, p.xy);
  float positive = evsmBound(m.xy, w.x, p.x, p.z);
  float negative = evsmBound(m.zw, w.y, p.y, p.z);
  return reduceLightBleeding(min(positive, negative), p.w);
}

// EVSM, two moments: the positive warp only.
vec4 encodeEvsm2(float z, vec4 p) {
  float w = evsmWarp(z, p.xy).x;
  return vec4(w, w * w, 0.0, 0.0);
}
float visibilityEvsm2(vec4 m, float t, vec4 p) {
  return reduceLightBleeding(evsmBound(m.xy, evsmWarp(t, p.xy).x, p.x, p.z), p.w);
}

// --- MSM (Peters & Klein 2015) ----------------------------------------------------------

vec4 msmPowers(float z) {
  float z2 = z * z;
  return vec4(z, z2, z2 * z, z2 * z2);
}

// The paper's optimized 16-bit quantization: q = A·b + (0.035955884801, 0, 0, 0) maps the
// moments b = (z, z², z³, z⁴) of every depth distribution on [0, 1] into [0, 1]⁴ while
// spreading them over the cube, so 16-bit UNORM rounding costs little. GLSL's mat4 takes
// columns: column i holds the coefficients of b_i in the four outputs.
const mat4 kMsmQuantize = mat4(
    -2.07224649, 13.7948857237, 0.105877704, 9.7924062118,
    32.23703778, -59.4683975703, -1.9077466311, -33.7652110555,
    -68.571074599, 82.0359750338, 9.3496555107, 47.9456096605,
    39.3703274134, -35.364903257, -6.6543490743, -23.9728048165);
// A⁻¹, also as printed in the paper (the tests check A⁻¹·A = I and the round trip).
const mat4 kMsmDequantize = mat4(
    0.2227744146, 0.1549679261, 0.1451988946, 0.163127443,
    0.0771972861, 0.1394629426, 0.2120202157, 0.2591432266,
    0.7926986636, 0.7963415838, 0.7258694464, 0.6539092497,
    0.0319417555, -0.1722823173, -0.2758014811, -0.3376131734);
const vec4 kMsmQuantizeOffset = vec4(0.035955884801, 0.0, 0.0, 0.0);

vec4 msmQuantize(vec4 b) { return kMsmQuantize * b + kMsmQuantizeOffset; }
vec4 msmDequantize(vec4 q) { return kMsmDequantize * (q - kMsmQuantizeOffset); }

// Hamburger 4MSM (the paper's Algorithm 3): visibility 1 − G, G the sharpest lower bound
// of the shadow intensity P(z < t) over all distributions with the moments b.
//  1. Bias towards the moments (0.5, 0.5, 0.5, 0.5) (depths 0 and 1, half each), which keeps
//     the Hankel matrix B = [[1,b1,b2],[b1,b2,b3],[b2,b3,b4]] positive definite.
//  2. Solve B·c = (1, t, t²) by Cholesky (here as L·D·Lᵀ: no square roots).
//  3. The roots z2 ≤ z3 of c1 + c2·z + c3·z² and t itself carry the three-point
//     distribution that matches b; G is the weight of its points left of t, from
//     Lagrange interpolation: weight(zi) = E[Π_{j≠i}(z − zj)] / Π_{j≠i}(zi − zj).
float msmHamburger(vec4 moments, float t, float alpha) {
  vec4 b = mix(moments, vec4(0.5), alpha);
  // L·D·Lᵀ of B: D = (1, d2, d3), L's below-diagonal entries (b1, b2; l32).
  float d2 = b.y - b.x * b.x;
  float l32 = (b.z - b.x * b.y) / d2;
  float d3 = max(b.w - b.y * b.y - l32 * l32 * d2, 1e-30);  // ≤ 0 only from rounding
  // Forward substitution L·y = (1, t, t²), scaling by D, back substitution Lᵀ·c = y.
  float y2 = t - b.x;
  float y3 = t * t - b.y - l32 * y2;
  float c3 = y3 / d3;
  float c2 = y2 / d2 - l32 * c3;
  float c1 = 1.0 - b.x * c2 - b.y * c3;
  // A vanishing c3 (t exactly at a degenerate point) sends one root to infinity; a tiny
  // c3 keeps it finite and far away, which gives the same branch below.
  if (abs(c3) < 1e-20) c3 = 1e-20;
  float halfP = 0.5 * c2 / c3;
  float root = sqrt(max(halfP * halfP - c1 / c3, 0.0));
  float z2 = -halfP - root, z3 = -halfP + root;
  float g;
  if (t <= z2) {
    g = 0.0;  // t in front of all three points
  } else if (t <= z3) {
    g = (t * z3 - b.x * (t + z3) + b.y) / max((z3 - z2) * (t - z2), 1e-30);  // weight of z2
  } else {
    g = 1.0 - (z2 * z3 - b.x * (z2 + z3) + b.y) / max((t - z2) * (t - z3), 1e-30);  // 1 − weight of t
  }
  // Degenerate input (bias 0 with one depth and rounding) can still produce NaN; fall back
  // to a plain test against the mean rather than let it reach the visibility buffer.
  if (isnan(g) || isinf(g)) g = t > b.x ? 1.0 : 0.0;
  return 1.0 - clamp(g, 0.0, 1.0);
}

// The receiver's depth moved towards the light by the depth bias. Where a texel's filter
// saw one depth z (a lit surface, its own occluder), t ≈ z up to interpolation rounding,
// and there the bound falls from 1 (t ≤ z) towards 0 over a width set by α: t lies on the
// steepest part of the solve, where an ulp of t or of the moments moves the visibility
// anywhere in [0, 1] (dark specks on lit surfaces, and different ones per compiler). Moved
// in front of z by more than the moments' rounding, t reads 1 whatever the rounding.
float msmBiasedDepth(float t, float depthBias) { return t - depthBias; }

// MSM with 32-bit floats: the plain moments. p = (moment_bias, depth_bias, -, -).
vec4 encodeMsm32(float z, vec4 p) { return msmPowers(z); }
float visibilityMsm32(vec4 m, float t, vec4 p) { return msmHamburger(m, msmBiasedDepth(t, p.y), p.x); }

// MSM with 16-bit UNORM and the optimized quantization (filtering commutes with the affine
// map, so the blurred texels dequantize to the blurred moments; so does the bias, a convex
// combination: mixing before or after dequantizing differs only by float rounding).
vec4 encodeMsm16(float z, vec4 p) { return msmQuantize(msmPowers(z)); }
float visibilityMsm16(vec4 m, float t, vec4 p) {
  return msmHamburger(msmDequantize(m), msmBiasedDepth(t, p.y), p.x);
}
