// Revectorization-based shadow mapping (RBSM): the building blocks every technique of this
// family shares (Macedo & Apolinário, GI 2016, §3.1; Unity listing 3 for computeRD).
// Each technique's own visibility function lives in its own file and includes this one.
// Unity listings: Macedo, Teixeira, Apolinário & Agüero, "Hard Shadow Anti-Aliasing for Spot
// Lights in a Game Engine", SBGames 2017.
//
// Conventions:
// - A sample is a light-space point (uv in [0,1]², light depth z). Its texel is
//   floor(uv·size) and p = fract(uv·size) its position inside that texel.
// - s ∈ {0 shadow, 1 lit}: the nearest depth test of glsl/shadow_test.glsl.
// - d = |N − s| for the 4 neighbours (left, right, bottom, top) one texel apart (eq. 3 of
//   EDTSM*). Neighbours outside the map count as equal to s: the map's border (which
//   reads as shadow) is not an edge of any occluder, and revectorizing along it would
//   bend the frustum's straight border.
// - For each axis, the traversal (computeRD) walks both directions and gives signed step
//   counts; the ONDS of that axis is the normalized distance α ∈ [0,1] of the sample from
//   the edge's end (the "corner" of the aliasing step). 1 − α is the paper's d_on (eq. 1).
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "testbed/glsl/shadow_test.glsl"
#include "testbed/glsl/units.glsl"

uniform int uMaxSearch;  // the paper's L: most texels walked per direction (16)
// Sloped-surface epsilon in normalized light depth (GI 2016 §3.1: 2.5e-5). One step of a
// 16-bit map is 1/65535 ≈ 1.5e-5, so with 16-bit depth ε must exceed that to matter at all.
uniform float uEpsilon;
uniform float uBias;     // constant depth bias, as sm's

const int RV_NO_END = 0;  // straight run (I): no end found on either side
const int RV_L = 1;       // one end found: an L-shaped step
const int RV_U = 2;       // both ends found: a U-shaped notch (also opposite neighbours)

bool rvInsideMap(ivec2 t) {
  return all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, uShadowMapSize));
}

// The shadow map's depths as depth_image.h lays them out: the texture itself, or an image
// of the same floats (cheaper to read one at a time on llvmpipe) in either of its layouts.
// rvStoredDepth(t): the stored depth of texel t (inside the map), the very value that
// shadowTestTexel's nearest lookup at the texel centre reads.
#if !defined(RV_DEPTH_TEXTURE) && !defined(RV_DEPTH_TEXELS) && !defined(RV_DEPTH_BLOCKS)
#error "compile with DepthImage::defines() (testbed/render/depth_image.h)"
#endif
#if defined(RV_DEPTH_TEXTURE)
float rvStoredDepth(ivec2 t) { return texelFetch(uShadowMap, t, 0).r; }
#elif defined(RV_DEPTH_TEXELS)
layout(r32f, binding = kDepthImageUnit) uniform readonly image2D uShadowImage;
float rvStoredDepth(ivec2 t) { return imageLoad(uShadowImage, t).r; }
#else
layout(rgba32f, binding = kDepthImageUnit) uniform readonly image2D uShadowImage;  // 2×2 blocks
float rvStoredDepth(ivec2 t) {
  const vec4 block = imageLoad(uShadowImage, t >> 1);
  const vec2 row = (t.y & 1) != 0 ? block.zw : block.xy;
  return (t.x & 1) != 0 ? row.y : row.x;
}
#endif

// The shadow test of glsl/shadow_test.glsl against an already fetched stored depth.
float rvTest(float z, float stored) { return z - uBias <= stored ? 1.0 : 0.0; }

// |test − s| of the texel t for light depth z; 0 outside the map (see the conventions).
float rvDiffers(ivec2 t, float z, float s) {
  return rvInsideMap(t) ? abs(rvTest(z, rvStoredDepth(t)) - s) : 0.0;
}

// 4-neighbour discontinuity (left, right, bottom, top) of texel t for light depth z.
vec4 rvDiscontinuity(ivec2 t, float z, float s) {
  return vec4(rvDiffers(t + ivec2(-1, 0), z, s), rvDiffers(t + ivec2(1, 0), z, s),
              rvDiffers(t + ivec2(0, -1), z, s), rvDiffers(t + ivec2(0, 1), z, s));
}

// The compressed discontinuity d_c of GI 2016 table 1: r = (2·left + right)/4,
// g = (2·bottom + top)/4 (0 none, .25 right/top, .5 left/bottom, .75 both), b = 1 − s
// (0 entering: lit next to shadow, 1 exiting: shadowed next to lit).
vec3 rvCompress(vec4 d, float s) {
  return vec3((2.0 * d.x + d.y) * 0.25, (2.0 * d.z + d.w) * 0.25, 1.0 - s);
}

// computeRD: walks from `origin` along `dir`, at most uMaxSearch texels. Returns +n when
// the n-th texel's test flips relative to the origin (the edge's end), −n when the n-th
// texel no longer shares a discontinuity direction with the origin, leaves the map, or
// the search is exhausted (n = uMaxSearch + 1 then).
// Sloped surfaces (GI 2016 §3.1): when the walked texel's stored depth lies within ε of
// the receiver's depth, it is taken to be the receiver's own surface and z is lowered by
// ε before the test; as in the authors' code the lowering accumulates along the walk.
// Each texel is fetched once: the neighbour behind a step is the previous texel and the
// one ahead is the next step's texel, so a step fetches the one ahead and the two beside
// (3 fetches, not 5), and the first step's texel comes with the origin's classification;
// the tests themselves are redone with the current z, as before.
// storedOrigin and storedFirst are the stored depths of the origin and of its neighbour
// origin + dir (read by the caller's classification; storedFirst unread outside the map).
int rvComputeRD(ivec2 origin, ivec2 dir, float z, float s, vec4 dOrigin, float storedOrigin, float storedFirst) {
  ivec2 beside = abs(dir.yx);  // the perpendicular axis, towards +
  ivec2 t = origin + dir;
  if (!rvInsideMap(t)) return -1;
  // Loop invariants, so a step does only its tests: the origin's discontinuity in the
  // step's own order (behind, ahead, beside −, beside +), and whether the rows (columns)
  // beside the walk lie inside the map (a step's texel is inside, so its neighbours
  // beside are iff their row is).
  bool towardsPositive = dir.x + dir.y > 0;
  vec2 originAlong = dir.x != 0 ? dOrigin.xy : dOrigin.zw;
  vec4 wanted = vec4(towardsPositive ? originAlong : originAlong.yx, dir.x != 0 ? dOrigin.zw : dOrigin.xy);
  bool lowInside = rvInsideMap(origin - beside), highInside = rvInsideMap(origin + beside);
  bool s1 = s == 1.0;
  float storedBehind = storedOrigin;
  float stored = storedFirst;
  int n = 1;
  for (int i = 0; i < uMaxSearch; ++i) {
    if (abs(z - stored) < uEpsilon) z -= uEpsilon;
    float zb = z - uBias;  // rvTest's
    if ((zb <= stored) != s1) return n;
    ivec2 ahead = t + dir;
    bool aheadInside = rvInsideMap(ahead);
    float storedAhead = aheadInside ? rvStoredDepth(ahead) : 0.0;
    float storedLow = lowInside ? rvStoredDepth(t - beside) : 0.0;
    float storedHigh = highInside ? rvStoredDepth(t + beside) : 0.0;
    // |test − s| of behind (inside: the origin or the last step), ahead and beside; 0
    // outside the map.
    bvec4 differs = bvec4((zb <= storedBehind) != s1, aheadInside && (zb <= storedAhead) != s1,
                          lowInside && (zb <= storedLow) != s1, highInside && (zb <= storedHigh) != s1);
    if (dot(vec4(differs), wanted) == 0.0) return -n;
    if (!aheadInside) return -(n + 1);
    storedBehind = stored;
    stored = storedAhead;
    t = ahead;
    ++n;
  }
  return -n;
}

struct RvAxis {
  float alpha;  // normalized distance from the end in [0,1]; 1 for a straight run
  int kind;     // RV_NO_END, RV_L, RV_U
};

// ONDS of one axis (GI 2016 eq. 1) from the signed steps towards −axis and +axis and the
// sample's sub-texel coordinate p along the axis. L = min(|a|+|b|−1, max_search); the
// distance to an end found at +n is (n − 1) + (1 − p) = n − p_o with p_o = p oriented
// towards that end, so α = (n − p_o)/L = 1 − d_on. U-shapes: a tent, 2·min(dist)/L.
RvAxis rvAxis(int toNeg, int toPos, float p) {
  float len = float(min(abs(toNeg) + abs(toPos) - 1, uMaxSearch));
  float distPos = float(toPos) - p;
  float distNeg = float(toNeg) - (1.0 - p);
  RvAxis a;
  if (toPos > 0 && toNeg > 0) {
    a.kind = RV_U;
    a.alpha = 2.0 * min(distPos, distNeg) / len;
  } else if (toPos > 0 || toNeg > 0) {
    a.kind = RV_L;
    a.alpha = (toPos > 0 ? distPos : distNeg) / len;
  } else {
    a.kind = RV_NO_END;
    a.alpha = 1.0;
  }
  a.alpha = clamp(a.alpha, 0.0, 1.0);
  return a;
}

// The stored depths of texel t and its 4 neighbours from two gathers at t's lower-left
// and upper-right corners (each returns the 2×2 block around its corner; a corner is half
// a texel from every texel centre, so the block is the same under any rounding of the
// coordinate). A gather without compare mode returns the stored values, the very ones
// texelFetch reads; outside the map the border depth 0, as the nearest lookup gets it.
// Gather order (GL 4.5 §8.14.2): (i0,j1), (i1,j1), (i1,j0), (i0,j0).
struct RvCross {
  float centre;
  vec4 neighbours;  // left, right, bottom, top
};

RvCross rvGatherCross(ivec2 t) {
  vec2 texel = 1.0 / vec2(uShadowMapSize);
  vec4 lowerLeft = textureGather(uShadowMap, vec2(t) * texel);       // left, centre, bottom, ·
  vec4 upperRight = textureGather(uShadowMap, vec2(t + 1) * texel);  // top, ·, right, centre
  return RvCross(lowerLeft.y, vec4(lowerLeft.x, upperRight.z, lowerLeft.z, upperRight.x));
}

struct RvSample {
  float s;        // shadow test of the sample
  vec4 d;         // its discontinuity
  bool edge;      // traversed: an edge texel of a side the caller asked for
  RvAxis x, y;    // ONDS along the map's x and y axes (valid when edge)
  ivec2 texel;    // the sample's texel
  vec2 p;         // its position inside the texel
  RvCross cross;  // stored depths of the texel and its neighbours (rvClassify)
};


// The part of rvSample every pixel needs: shadow test, discontinuity and whether the texel
// is an edge to traverse (`edge`); the ONDS is left at "straight run". `bothSides` false:
// only lit texels (entering discontinuities) are edges, as single-pass SMSR has it.
// The same as rvClassifyFetched (one texelFetch per texel), from two gathers.
RvSample rvClassify(vec2 uv, float z, bool bothSides) {
  RvSample r;
  vec2 t = uv * vec2(uShadowMapSize);
  r.texel = ivec2(floor(t));
  r.p = t - floor(t);
  r.x = RvAxis(1.0, RV_NO_END);
  r.y = RvAxis(1.0, RV_NO_END);
  RvCross c = rvGatherCross(r.texel);
  r.cross = c;
  r.s = rvTest(z, c.centre);
  // |test − s| per neighbour, 0 outside the map (see the conventions).
  bvec4 inside = bvec4(r.texel.x > 0, r.texel.x + 1 < uShadowMapSize.x, r.texel.y > 0, r.texel.y + 1 < uShadowMapSize.y);
  vec4 tests = vec4(lessThanEqual(vec4(z - uBias), c.neighbours));
  r.d = mix(vec4(0.0), abs(tests - r.s), inside);
  // No edge outside the map, nor on the shadowed side unless asked for.
  if (!rvInsideMap(r.texel) || (r.s == 0.0 && !bothSides)) r.d = vec4(0.0);
  r.edge = r.d != vec4(0.0);
  return r;
}

// rvClassify the straightforward way, one texelFetch per texel (the unit tests compare
// the two).
RvSample rvClassifyFetched(vec2 uv, float z, bool bothSides) {
  RvSample r;
  vec2 t = uv * vec2(uShadowMapSize);
  r.texel = ivec2(floor(t));
  r.p = t - floor(t);
  r.edge = false;
  r.d = vec4(0.0);
  r.x = RvAxis(1.0, RV_NO_END);
  r.y = RvAxis(1.0, RV_NO_END);
  // Outside the map the border depth 0 answers, as shadowTest's lookup gets it.
  bool inside = rvInsideMap(r.texel);
  r.s = rvTest(z, inside ? rvStoredDepth(r.texel) : 0.0);
  if (!inside) return r;  // no edge outside the map
  r.cross = RvCross(rvStoredDepth(r.texel), vec4(rvStoredDepth(r.texel + ivec2(-1, 0)), rvStoredDepth(r.texel + ivec2(1, 0)),
                                                 rvStoredDepth(r.texel + ivec2(0, -1)), rvStoredDepth(r.texel + ivec2(0, 1))));
  if (r.s == 0.0 && !bothSides) return r;
  r.d = rvDiscontinuity(r.texel, z, r.s);
  r.edge = r.d != vec4(0.0);
  return r;
}

// The ONDS of both axes of a classified sample that is an edge (others are returned as
// they are); r.cross must hold its texel's stored depths.
RvSample rvTraverse(RvSample r, float z) {
  if (!r.edge) return r;
  float o = r.cross.centre;
  vec4 n = r.cross.neighbours;
  r.x = rvAxis(rvComputeRD(r.texel, ivec2(-1, 0), z, r.s, r.d, o, n.x), rvComputeRD(r.texel, ivec2(1, 0), z, r.s, r.d, o, n.y), r.p.x);
  r.y = rvAxis(rvComputeRD(r.texel, ivec2(0, -1), z, r.s, r.d, o, n.z), rvComputeRD(r.texel, ivec2(0, 1), z, r.s, r.d, o, n.w), r.p.y);
  return r;
}

// Shadow test, discontinuity and (for edge texels) the ONDS of both axes.
RvSample rvSample(vec2 uv, float z, bool bothSides) { return rvTraverse(rvClassify(uv, z, bothSides), z); }
