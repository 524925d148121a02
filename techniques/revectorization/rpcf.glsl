// The kernel width shared by the two RPCF variants (rpcf_smsr.glsl, rpcf_rsmss.glsl), odd:
// the k×k block is centred on the receiver's texel. The screen passes compile it in
// (RPCF_KERNEL), so the tap loops unroll; the unit-test probe sets the uniform.
#include "testbed/glsl/kernel.glsl"

#ifdef RPCF_KERNEL
const int uKernel = RPCF_KERNEL;
#else
uniform int uKernel;
#endif

// The k taps of a row as bits 0 … k − 1 of one word, the rim texels beside them apart: so
// every odd k up to 31 (the kernel parameter's maximum, the EDTSM* paper's widest) fits.
uint rpcfTapBits() { return (1u << uint(uKernel)) - 1u; }

// The rows the block tests hold: its k + 2 (taps and rim) and a spare, as gathers read
// them in pairs.
#ifdef RPCF_KERNEL
const int kRpcfRows = RPCF_KERNEL + 3;
#else
const int kRpcfRows = 34;  // the widest kernel, 31
#endif

// The shadow tests of row centre.y + dy as (taps, rim): bit j of taps is the texel
// centre.x − h + j (j = 0 … k − 1), bits 0 and 1 of rim the texels centre.x − h − 1 and
// centre.x + h + 1 beside the block (callers keep the block inside the map). One
// texelFetch per texel: the straightforward version of rpcfBlockTests (the unit tests
// compare them).
uvec2 rpcfRowTests(ivec2 centre, int dy, int h, float depth) {
  uvec2 row = uvec2(0u);
  for (int j = 0; j <= 2 * h; ++j)
    row.x |= uint(rvTest(depth, rvStoredDepth(centre + ivec2(j - h, dy)))) << uint(j);
  row.y = uint(rvTest(depth, rvStoredDepth(centre + ivec2(-h - 1, dy)))) |
          (uint(rvTest(depth, rvStoredDepth(centre + ivec2(h + 1, dy)))) << 1u);
  return row;
}

// The (taps, rim) bit of the block's column b (0: the rim texel left of the block, 1 … k:
// the taps, k + 1: the rim texel right of it, beyond: none) for the test t.
uvec2 rpcfColumnBit(int b, float t) {
  uint bit = uint(t);
  if (b == 0) return uvec2(0u, bit);
  if (b <= uKernel) return uvec2(bit << uint(b - 1), 0u);
  return b == uKernel + 1 ? uvec2(0u, bit << 1u) : uvec2(0u);
}

// rows[i] = rpcfRowTests(centre, i − h − 1, h, depth) for the block's rows i = 0 … k + 1,
// from one gather per 2×2 texels ((k+3)²/4 gathers, not (k+2)² fetches; rvGatherCross
// says why a gather reads the stored values). Row k + 2 is a spare.
void rpcfBlockTests(ivec2 centre, float depth, out uvec2 rows[kRpcfRows]) {
  int h = uKernel / 2;
  vec2 texel = 1.0 / vec2(uShadowMapSize);
  float z = depth - uBias;  // rvTest's
  for (int i = 0; i < uKernel + 2; i += 2) {
    uvec2 low = uvec2(0u), high = uvec2(0u);
    for (int b = 0; b < uKernel + 2; b += 2) {
      // Columns b, b + 1 of rows i, i + 1, around their shared corner; gather order
      // (i0,j1), (i1,j1), (i1,j0), (i0,j0).
      vec4 t = vec4(lessThanEqual(vec4(z), textureGather(uShadowMap, vec2(centre + ivec2(b - h, i - h)) * texel)));
      low |= rpcfColumnBit(b, t.w) | rpcfColumnBit(b + 1, t.z);
      high |= rpcfColumnBit(b, t.x) | rpcfColumnBit(b + 1, t.y);
    }
    rows[i] = low;
    rows[i + 1] = high;
  }
}

// Whether the taps' texels, computed as the variants' visibility functions compute them
// (kernelTapUv), form the k×k block around `centre` with a one-texel rim
// inside the map: then the row masks below describe every tap exactly.
// kernelTapUv works per component, so the column of tap (x, y)'s texel depends on x alone
// and its row on y alone: all k² taps land right iff the k taps (i, i) of the diagonal
// do, which is k checks instead of k² (rpcfRegularBlockPlain, the straightforward one, is
// what the unit tests compare it with).
bool rpcfRegularBlock(vec2 uv, ivec2 centre) {
  int h = uKernel / 2;
  vec2 size = vec2(uShadowMapSize);
  bool regular = rvInsideMap(centre - ivec2(h + 1)) && rvInsideMap(centre + ivec2(h + 1));
  for (int i = -h; i <= h; ++i) regular = regular && ivec2(floor(kernelTapUv(uv, i, i) * size)) == centre + ivec2(i);
  return regular;
}

bool rpcfRegularBlockPlain(vec2 uv, ivec2 centre) {
  int h = uKernel / 2;
  vec2 size = vec2(uShadowMapSize);
  bool regular = rvInsideMap(centre - ivec2(h + 1)) && rvInsideMap(centre + ivec2(h + 1));
  for (int y = -h; y <= h; ++y)
    for (int x = -h; x <= h; ++x)
      regular = regular && ivec2(floor(kernelTapUv(uv, x, y) * size)) == centre + ivec2(x, y);
  return regular;
}

// The taps of `row` whose texel is an edge of the sides traversed: a 4-neighbour's test
// differs (left and right from the row and its rim; `below`, `above`: the taps of the rows
// beside).
uint rpcfRowEdges(uint below, uvec2 row, uint above, bool bothSides) {
  uint left = (row.x << 1u) | (row.y & 1u);
  uint right = (row.x >> 1u) | ((row.y >> 1u) << uint(uKernel - 1));
  uint differs = (row.x ^ left) | (row.x ^ right) | (row.x ^ above) | (row.x ^ below);
  return differs & (bothSides ? rpcfTapBits() : (row.x & rpcfTapBits()));
}

// The screen pass's classification (rpcf_tiles.h): uRpcfTiles holds the least and
// greatest stored depth of each 2×2 texel tile with an apron of h = k/2 texels, i.e. of
// the texels 2·tile − h … 2·tile + 1 + h a side. Two tiles side by side span k + 3
// texels, and those from tile (c − 1)/2 (rounded down) span the block and its rim,
// c − h − 1 … c + h + 1 around the centre c; four texelFetches read those 2×2 tiles'
// bounds. Where the receiver's depth tests lit against the least of all four, or shadowed
// against the greatest, every tap's texel and neighbour tests alike, so no tap is an edge
// of either side and v is 1 or 0, the plain loop's sum of k² equal tests over k²; the
// rest is left to the edge draw, as is a block that is not regular (rpcfRegularBlock,
// which also keeps the four tiles inside the map). Both variants: a block that tests
// alike has no edge of either side.
uniform sampler2D uRpcfTiles;

bool rpcfTileClassify(vec2 uv, float depth, out float v) {
  ivec2 centre = ivec2(floor(uv * vec2(uShadowMapSize)));
  ivec2 first = (centre - 1) / 2;  // centre ≥ h + 1 ≥ 1 where the block is regular
  vec2 b00 = texelFetch(uRpcfTiles, first, 0).rg, b10 = texelFetch(uRpcfTiles, first + ivec2(1, 0), 0).rg;
  vec2 b01 = texelFetch(uRpcfTiles, first + ivec2(0, 1), 0).rg, b11 = texelFetch(uRpcfTiles, first + 1, 0).rg;
  float z = depth - uBias;  // rvTest's
  bool lit = z <= min(min(b00.x, b10.x), min(b01.x, b11.x));
  bool shadowed = z > max(max(b00.y, b10.y), max(b01.y, b11.y));
  v = lit ? 1.0 : 0.0;
  return (lit || shadowed) && rpcfRegularBlock(uv, centre);
}

// The edge draw's walk over the taps (shared work across RPCF's taps): the variant calls
// its own tap visibility only on the edge taps that rpcfNextEdgeTap hands out, while the
// other taps add their shadow test from the row masks. The sum runs in the same tap order
// as the plain loop and every tap adds the same number, so the result is the same bits;
// the loop runs as often as a pixel has edge taps, not k² times. Where the block is not
// regular every tap counts as an edge, which is the plain loop.
struct RpcfTaps {
  vec2 uv;
  ivec2 centre;
  float depth;
  bool bothSides, regular;
  int y, next;           // the tap row, and the next tap of it to add
  uvec2 rows[kRpcfRows]; // rpcfBlockTests (unread where the block is not regular)
  uint pending;          // edge taps of row y not handed out yet (bits 0 … k − 1)
  float sum;
  vec2 tapUv;            // the edge tap handed out
  RvSample tap;          // its rvClassify
};

RpcfTaps rpcfBeginTaps(vec2 uv, float depth, bool bothSides) {
  RpcfTaps w;
  int h = uKernel / 2;
  w.uv = uv;
  w.depth = depth;
  w.bothSides = bothSides;
  w.centre = ivec2(floor(uv * vec2(uShadowMapSize)));
  w.regular = rpcfRegularBlock(uv, w.centre);
  w.y = -h - 1;
  w.next = uKernel;  // nothing of row −h − 1 to add
  rpcfBlockTests(w.centre, depth, w.rows);
  w.pending = 0u;
  w.sum = 0.0;
  w.tapUv = uv;
  return w;
}

// Adds the row's taps before tap `until` (exclusive) that are no edges.
void rpcfAddTests(inout RpcfTaps w, int until) {
  uint taps = w.rows[w.y + uKernel / 2 + 1].x;
  for (; w.next < until; ++w.next) w.sum += float((taps >> uint(w.next)) & 1u);
}

// Hands out the next edge tap (w.tapUv), adding the taps before it; false when done.
bool rpcfNextEdgeTap(inout RpcfTaps w) {
  int h = uKernel / 2;
  while (w.pending == 0u) {
    rpcfAddTests(w, uKernel);
    if (w.y == h) return false;
    ++w.y;
    int i = w.y + h + 1;
    w.pending = w.regular ? rpcfRowEdges(w.rows[i - 1].x, w.rows[i], w.rows[i + 1].x, w.bothSides) : rpcfTapBits();
    w.next = 0;
  }
  int tap = findLSB(w.pending);
  w.pending &= w.pending - 1u;
  rpcfAddTests(w, tap);
  w.next = tap + 1;
  w.tapUv = kernelTapUv(w.uv, tap - h, w.y);
  // Classified by its own gathers, not from the masks: the traversal needs the stored
  // depths of its cross (RvSample.cross), and an irregular block's masks say nothing.
  w.tap = rvClassify(w.tapUv, w.depth, w.bothSides);
  return true;
}

float rpcfEndTaps(RpcfTaps w) { return w.sum / float(uKernel * uKernel); }
