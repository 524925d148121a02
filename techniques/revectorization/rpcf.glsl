// The kernel width shared by the two RPCF variants (rpcf_smsr.glsl, rpcf_rsmss.glsl).
uniform int uKernel;  // odd: the k×k block is centred on the receiver's texel

// The shadow tests of the texels (centre.x − h − 1 … centre.x + h + 1, centre.y + dy) as
// bits 0 … k + 1 of a row mask (callers keep the block inside the map).
uint rpcfRowTests(ivec2 centre, int dy, int h, float depth) {
  uint bits = 0u;
  for (int i = 0; i <= 2 * h + 2; ++i)
    bits |= uint(rvTest(depth, rvStoredDepth(centre + ivec2(i - h - 1, dy)))) << uint(i);
  return bits;
}

// True, with the filtered v, where no tap's texel is an edge of the sides the variant
// traverses (`bothSides`); false sends the pixel to the full visibility function. The taps'
// k×k block and its one-texel rim are tested once, as row masks shared by neighbouring
// taps ((k+2)² fetches, not 5k²): a tap is an edge when a 4-neighbour's bit differs. Taps
// that are not edges are their shadow tests, 0 or 1, whose sum is an exact integer in any
// order, so v is the very number the visibility functions compute. Where the taps' texels
// (computed as those functions compute them) are not the regular block, or the block's
// rim leaves the map, the pixel takes the full path.
bool rpcfClassify(vec2 uv, float depth, bool bothSides, out float v) {
  int h = uKernel / 2;
  vec2 size = vec2(uShadowMapSize);
  vec2 texel = 1.0 / size;
  ivec2 centre = ivec2(floor(uv * size));
  bool regular = rvInsideMap(centre - ivec2(h + 1)) && rvInsideMap(centre + ivec2(h + 1));
  for (int y = -h; y <= h; ++y)
    for (int x = -h; x <= h; ++x)
      regular = regular && ivec2(floor((uv + vec2(x, y) * texel) * size)) == centre + ivec2(x, y);
  v = 0.0;
  if (!regular) return false;
  uint taps = ((1u << uint(uKernel)) - 1u) << 1u;
  uint below = rpcfRowTests(centre, -h - 1, h, depth);
  uint row = rpcfRowTests(centre, -h, h, depth);
  uint lit = 0u;
  bool edge = false;
  for (int y = -h; y <= h; ++y) {
    uint above = rpcfRowTests(centre, y + 1, h, depth);
    uint differs = (row ^ (row << 1u)) | (row ^ (row >> 1u)) | (row ^ above) | (row ^ below);
    uint traversed = bothSides ? taps : (row & taps);
    edge = edge || (differs & traversed) != 0u;
    lit += uint(bitCount(row & taps));
    below = row;
    row = above;
  }
  v = float(lit) / float(uKernel * uKernel);
  return !edge;
}
