// Feature transform, pass 2 (feature_transform.h): one invocation per column takes the
// lower envelope of the parabolas f_i(y) = (y - i)² + g(i)² over the rows i, g(i) being
// the column distance to row i's nearest seed (pass 1), as Meijster et al. 2000 do. Rows
// without a seed get g = uSize.x + uSize.y, farther than any real seed, so they never win
// while a real seed exists and no special case is needed. Everything is int32 and exact:
// the intersection of two parabolas is floored by integer division, which is all the
// envelope needs since it is only ever evaluated at integer rows.
//
// The including shader defines, before including this file,
//   const int kColumnSpan                        rows between two featureTransformSpanEnd()
//   void featureTransformStore(ivec2 pixel, ivec2 seed)
//                                                given each pixel's nearest seed, (-1, -1)
//                                                when the image has none, for the rows of
//                                                one column from the last to the first
//   void featureTransformSpanEnd(ivec2 pixel)    after the rows down to `pixel`, a multiple
//                                                of kColumnSpan or the range's first row
// (per-span work out of the per-pixel loop, as feature_transform_row_sweep.glsl's hooks);
// its main() calls featureTransformColumn(), or sets gColumn and calls
// featureTransformColumnRange() (a band of rows, below).
#include "testbed/glsl/units.glsl"

layout(local_size_x = 64) in;

uniform ivec2 uSize;
int gColumn;  // this invocation's column
layout(r32i, binding = kRowNearestImageUnit) uniform readonly iimage2D uRowNearest;
// Per column, a stack of (row i of a parabola, first row where it is the minimum); entry k
// of column x at texel (x, k). Images, not buffers, as in pass 1.
layout(rg32i, binding = kEnvelopeImageUnit) uniform iimage2D uEnvelope;

ivec2 envelopeAt(int k) { return imageLoad(uEnvelope, ivec2(gColumn, k)).xy; }
void setEnvelope(int k, ivec2 e) { imageStore(uEnvelope, ivec2(gColumn, k), ivec4(e, 0, 0)); }

int g(int i) {
  const int seedX = imageLoad(uRowNearest, ivec2(gColumn, i)).x;
  return seedX < 0 ? uSize.x + uSize.y : abs(gColumn - seedX);
}
int f(int y, int i, int gi) { return (y - i) * (y - i) + gi * gi; }

// The envelope of the rows u in [rowsFrom, rowsTo) whose g(u) <= maxG, built for the rows
// [from, to) only and stored for those (from <= rowsFrom is not needed; rows outside the
// output range still win inside it). Rows are visited in increasing order, so on a tie the
// smaller row keeps it: the result is the least (distance², row) over the rows taken, with
// the row's own tie (the left seed) from pass 1. With every row taken (maxG >=
// uSize.x + uSize.y) it is the exact transform of the column.
void featureTransformColumnRange(int from, int to, int rowsFrom, int rowsTo, int maxG) {
  // Build: the stack holds the envelope's parabolas in row order, each with the first row
  // where it is the minimum; the top one wins up to the last row seen.
  int top = -1;
  for (int u = rowsFrom; u < rowsTo; ++u) {
    const int gu = g(u);
    if (gu > maxG) continue;
    // Pop parabolas that u beats (strictly) where they start to win.
    while (top >= 0) {
      const ivec2 e = envelopeAt(top);
      if (f(e.y, e.x, g(e.x)) <= f(e.y, u, gu)) break;
      --top;
    }
    if (top < 0) {
      top = 0;
      setEnvelope(0, ivec2(u, from));
    } else {
      // u wins strictly from floor(sep) + 1 on, sep = ((u² - i²) + (g(u)² - g(i)²)) / 2(u - i);
      // the top still wins (or ties) at its own start >= from >= 0, so the numerator is >= 0
      // and integer division floors.
      const int i = envelopeAt(top).x;
      const int gi = g(i);
      const int start = 1 + ((u * u - i * i) + (gu * gu - gi * gi)) / (2 * (u - i));
      if (start < to) setEnvelope(++top, ivec2(u, start));
    }
  }
  // Walk the rows from the last to the first, popping a parabola once past its start, in
  // spans that end at multiples of kColumnSpan and at `from`.
  for (int spanEnd = to; spanEnd > from;) {
    const int spanStart = max(from, (spanEnd - 1) / kColumnSpan * kColumnSpan);
    for (int y = spanEnd - 1; y >= spanStart; --y) {
      ivec2 seed = ivec2(-1);
      if (top >= 0) {
        const ivec2 e = envelopeAt(top);
        const int seedX = imageLoad(uRowNearest, ivec2(gColumn, e.x)).x;
        if (seedX >= 0) seed = ivec2(seedX, e.x);
        if (y == e.y) --top;
      }
      featureTransformStore(ivec2(gColumn, y), seed);
    }
    featureTransformSpanEnd(ivec2(gColumn, spanStart));
    spanEnd = spanStart;
  }
}

void featureTransformColumn() {
  gColumn = int(gl_GlobalInvocationID.x);
  if (gColumn >= uSize.x) return;
  featureTransformColumnRange(0, uSize.y, 0, uSize.y, uSize.x + uSize.y);
}
