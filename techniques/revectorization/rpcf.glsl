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

// The shadow tests of row centre.y + dy as (taps, rim): bit j of taps is the texel
// centre.x − h + j (j = 0 … k − 1), bits 0 and 1 of rim the texels centre.x − h − 1 and
// centre.x + h + 1 beside the block (callers keep the block inside the map).
uvec2 rpcfRowTests(ivec2 centre, int dy, int h, float depth) {
  uvec2 row = uvec2(0u);
  for (int j = 0; j <= 2 * h; ++j)
    row.x |= uint(rvTest(depth, rvStoredDepth(centre + ivec2(j - h, dy)))) << uint(j);
  row.y = uint(rvTest(depth, rvStoredDepth(centre + ivec2(-h - 1, dy)))) |
          (uint(rvTest(depth, rvStoredDepth(centre + ivec2(h + 1, dy)))) << 1u);
  return row;
}

// Whether the taps' texels, computed as the variants' visibility functions compute them
// (kernelTapUv), form the k×k block around `centre` with a one-texel rim
// inside the map: then the row masks below describe every tap exactly.
bool rpcfRegularBlock(vec2 uv, ivec2 centre) {
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

// True, with the filtered v, where no tap's texel is an edge of the sides the variant
// traverses (`bothSides`); false sends the pixel to the edge draw. The taps' k×k block and
// its one-texel rim are tested once, as row masks shared by neighbouring taps ((k+2)²
// fetches, not 5k²). Taps that are not edges are their shadow tests, 0 or 1, whose sum is
// an exact integer in any order, so v is the very number the visibility functions give.
bool rpcfClassify(vec2 uv, float depth, bool bothSides, out float v) {
  int h = uKernel / 2;
  ivec2 centre = ivec2(floor(uv * vec2(uShadowMapSize)));
  v = 0.0;
  if (!rpcfRegularBlock(uv, centre)) return false;
  uvec2 below = rpcfRowTests(centre, -h - 1, h, depth);
  uvec2 row = rpcfRowTests(centre, -h, h, depth);
  uint lit = 0u;
  bool edge = false;
  for (int y = -h; y <= h; ++y) {
    uvec2 above = rpcfRowTests(centre, y + 1, h, depth);
    edge = edge || rpcfRowEdges(below.x, row, above.x, bothSides) != 0u;
    lit += uint(bitCount(row.x & rpcfTapBits()));
    below = row;
    row = above;
  }
  v = float(lit) / float(uKernel * uKernel);
  return !edge;
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
  uvec2 row, above;      // row tests (taps, rim) of rows y and y + 1
  uint pending;          // edge taps of row y not handed out yet (bits 0 … k − 1)
  float sum;
  vec2 tapUv;            // the edge tap handed out
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
  w.row = w.regular ? rpcfRowTests(w.centre, -h - 1, h, depth) : uvec2(0u);
  w.above = w.regular ? rpcfRowTests(w.centre, -h, h, depth) : uvec2(0u);
  w.pending = 0u;
  w.sum = 0.0;
  w.tapUv = uv;
  return w;
}

// Adds the row's taps before tap `until` (exclusive) that are no edges.
void rpcfAddTests(inout RpcfTaps w, int until) {
  for (; w.next < until; ++w.next) w.sum += float((w.row.x >> uint(w.next)) & 1u);
}

// Hands out the next edge tap (w.tapUv), adding the taps before it; false when done.
bool rpcfNextEdgeTap(inout RpcfTaps w) {
  int h = uKernel / 2;
  while (w.pending == 0u) {
    rpcfAddTests(w, uKernel);
    if (w.y == h) return false;
    ++w.y;
    uvec2 below = w.row;
    w.row = w.above;
    w.above = w.regular ? rpcfRowTests(w.centre, w.y + 1, h, w.depth) : uvec2(0u);
    w.pending = w.regular ? rpcfRowEdges(below.x, w.row, w.above.x, w.bothSides) : rpcfTapBits();
    w.next = 0;
  }
  int tap = findLSB(w.pending);
  w.pending &= w.pending - 1u;
  rpcfAddTests(w, tap);
  w.next = tap + 1;
  w.tapUv = kernelTapUv(w.uv, tap - h, w.y);
  return true;
}

float rpcfEndTaps(RpcfTaps w) { return w.sum / float(uKernel * uKernel); }
