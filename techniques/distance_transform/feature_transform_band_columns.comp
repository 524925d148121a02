#version 450 core
// Banded feature transform, phases 2 and 3 (feature_transform_banded.h), per column, its
// rows cut into bands of uBand rows. The sites (feature_transform_band.glsl) that win some
// row of [0, uSize.y) form the column's lower envelope, kept as a doubly linked list in
// uLinks (texel (x, row) of each site: its previous and next site).
// STEP 1: each band builds the envelope of its own sites (a stack; a site popped there
//         loses every row to two of its own neighbours, so to the whole column too);
// STEP 2: adjacent groups of uGroup bands merge, pairwise (a log2(bands) rounds): the
//         column's envelope of two groups, every row of the first group below every row of
//         the second, is a prefix of the first's list joined to a suffix of the second's,
//         so only sites at the join are popped;
// STEP 3: each band of the list walks its surviving sites and records, for every band
//         whose first row falls in a site's rows, that site;
// STEP 4: each band colours its rows from that site on, moving along the list.
#include "techniques/distance_transform/feature_transform_band.glsl"

layout(r32i, binding = kBandRowNearestImageUnit) uniform readonly iimage2D uRowNearest;
layout(rg32i, binding = kLinksImageUnit) uniform iimage2D uLinks;
layout(rg32i, binding = kBandEndsImageUnit) uniform iimage2D uBandEnds;
layout(r32i, binding = kBandStartImageUnit) uniform iimage2D uBandStart;
layout(rg32i, binding = kEdtsmOutputImageUnit) uniform writeonly iimage2D uNearest;
uniform int uGroup;  // STEP 2: bands a group

int gColumn;

int seedColumn(int row) { return imageLoad(uRowNearest, ivec2(gColumn, row)).x; }
int g(int row) { return abs(gColumn - seedColumn(row)); }
ivec2 links(int row) { return imageLoad(uLinks, ivec2(gColumn, row)).xy; }
void setLinks(int row, ivec2 l) { imageStore(uLinks, ivec2(gColumn, row), ivec4(l, 0, 0)); }
// The first row a site wins, given its previous site (-1: none).
int startOf(int previous, int site, int gSite) { return previous < 0 ? 0 : beatsFrom(previous, g(previous), site, gSite); }
// The row after the last a site wins, given its next site (-1: none).
int endOf(int site, int gSite, int next) { return next < 0 ? uSize.y : beatsFrom(site, gSite, next, g(next)); }

#if STEP == 1
void proximateSites(int band) {
  const int from = band * uBand, to = min(from + uBand, uSize.y);
  int first = -1, top = -1, gTop = 0, below = -1;  // below: the site under the top
  for (int u = from; u < to; ++u) {
    const int seed = seedColumn(u);
    if (seed < 0) {
      setLinks(u, ivec2(kNotSite));
      continue;
    }
    const int gu = abs(gColumn - seed);
    // Pop the top while u beats it from the row it starts winning.
    while (top >= 0 && beatsFrom(top, gTop, u, gu) <= startOf(below, top, gTop)) {
      setLinks(top, ivec2(kNotSite));
      top = below;
      if (top >= 0) {
        gTop = g(top);
        below = links(top).x;
      }
    }
    if (top >= 0 && beatsFrom(top, gTop, u, gu) >= uSize.y) {  // u wins no row of the column
      setLinks(u, ivec2(kNotSite));
      continue;
    }
    if (top >= 0)
      setLinks(top, ivec2(below, u));
    else
      first = u;
    setLinks(u, ivec2(top, -1));
    below = top;
    top = u;
    gTop = gu;
  }
  imageStore(uBandEnds, ivec2(gColumn, band), ivec4(top < 0 ? ivec2(-1) : ivec2(first, top), 0, 0));
}
#elif STEP == 2
// Merges the group of bands starting at `a` with the one starting at `b`, into a's ends.
void merge(int a, int b) {
  const ivec2 ends = imageLoad(uBandEnds, ivec2(gColumn, a)).xy, endsB = imageLoad(uBandEnds, ivec2(gColumn, b)).xy;
  int last = ends.y, first = endsB.x;  // the join: the first group's last site, the second's first
  if (last < 0 || first < 0) {
    if (last < 0) imageStore(uBandEnds, ivec2(gColumn, a), ivec4(endsB, 0, 0));
    return;
  }
  int gLast = g(last), gFirst = g(first);
  for (;;) {
    const int lastBefore = links(last).x;
    if (beatsFrom(last, gLast, first, gFirst) <= startOf(lastBefore, last, gLast)) {
      setLinks(last, ivec2(kNotSite));
      last = lastBefore;
      if (last < 0) break;
      gLast = g(last);
      continue;
    }
    const int firstAfter = links(first).y;
    if (beatsFrom(last, gLast, first, gFirst) >= endOf(first, gFirst, firstAfter)) {
      setLinks(first, ivec2(kNotSite));
      first = firstAfter;
      if (first < 0) break;
      gFirst = g(first);
      continue;
    }
    break;
  }
  if (last >= 0) setLinks(last, ivec2(links(last).x, first));
  if (first >= 0) setLinks(first, ivec2(last, links(first).y));
  imageStore(uBandEnds, ivec2(gColumn, a), ivec4(last >= 0 ? ends.x : first, first >= 0 ? endsB.y : last, 0, 0));
}
#elif STEP == 3
void recordStarts(int band) {
  const int from = band * uBand, to = min(from + uBand, uSize.y);
  for (int u = from; u < to; ++u) {
    const ivec2 l = links(u);
    if (l.x == kNotSite) continue;
    const int gu = g(u);
    const int start = startOf(l.x, u, gu), end = min(endOf(u, gu, l.y), uSize.y);
    for (int b = (start + uBand - 1) / uBand; b * uBand < end; ++b) imageStore(uBandStart, ivec2(gColumn, b), ivec4(u));
  }
}
#else
void colour(int band) {
  const int from = band * uBand, to = min(from + uBand, uSize.y);
  int site = imageLoad(uBandStart, ivec2(gColumn, band)).x;
  if (site < 0) {
    for (int y = from; y < to; ++y) imageStore(uNearest, ivec2(gColumn, y), ivec4(-1));
    return;
  }
  int seed = seedColumn(site), next = links(site).y;
  int end = endOf(site, abs(gColumn - seed), next);
  for (int y = from; y < to; ++y) {
    while (y >= end) {
      site = next;
      seed = seedColumn(site);
      next = links(site).y;
      end = endOf(site, abs(gColumn - seed), next);
    }
    imageStore(uNearest, ivec2(gColumn, y), ivec4(seed, site, 0, 0));
  }
}
#endif

void main() {
  gColumn = int(gl_GlobalInvocationID.x);
  const int band = int(gl_GlobalInvocationID.y), bands = (uSize.y + uBand - 1) / uBand;
  if (gColumn >= uSize.x) return;
#if STEP == 2
  const int a = 2 * band * uGroup, b = a + uGroup;
  if (b < bands) merge(a, b);
#else
  if (band >= bands) return;
#if STEP == 1
  proximateSites(band);
#elif STEP == 3
  recordStarts(band);
#else
  colour(band);
#endif
#endif
}
