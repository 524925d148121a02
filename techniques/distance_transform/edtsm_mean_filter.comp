#version 450 core
// EDTSM's mean filter (edtsm_mean_filter.glsl) on the tiles where it can change a pixel
// (edtsm_filter_tiles.h), one direction per dispatch (COLUMNS defined: along y into the
// R32F visibility, else along x into an RG32F image for the second direction). A workgroup
// is one tile; an invocation filters a segment of kSegment consecutive pixels of one line,
// the 8 lanes of a SIMD vector being 8 neighbouring lines. Each tap of the segment's
// windows is fetched once and added to every window it falls in, in increasing order as
// the fragment shader adds a pixel's taps, so every sum is the same float, bit for bit,
// for fewer fetches per pixel and tap (four consecutive pixels measured cheaper than eight:
// the union of eight windows is longer, and every tap costs each window a test).
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "testbed/glsl/units.glsl"
#include "techniques/distance_transform/edtsm_mean_filter.glsl"
#include "techniques/distance_transform/edtsm_tiles.glsl"

const int kSegment = 4;  // kTile = 4 kSegment
layout(local_size_x = 16, local_size_y = 4) in;  // kTile lines, four segments each

#ifdef COLUMNS
const ivec2 kAlong = ivec2(0, 1);
layout(r32f, binding = kEdtsmOutputImageUnit) uniform writeonly image2D uFiltered;
#else
const ivec2 kAlong = ivec2(1, 0);
layout(rg32f, binding = kEdtsmOutputImageUnit) uniform writeonly image2D uFiltered;
#endif
// uIntensity again, as an image: on llvmpipe an imageLoad costs fewer instructions than a
// texel fetch of the same texel, and every tap of every window is one.
layout(rg32f, binding = kEdtsmInputImageUnit) uniform readonly image2D uIntensityImage;
// The tiles to filter (edtsm_filter_tiles.comp): x + y · tiles.x each, after the dispatch's
// indirect arguments.
layout(std430, binding = kTileListBufferBinding) readonly buffer Tiles { uint tileList[]; };
uniform int uListOffset;  // index of this direction's first tile
uniform int uTileColumns;

void main() {
  const uint index = tileList[uListOffset + int(gl_WorkGroupID.x)];
  const ivec2 tile = ivec2(int(index) % uTileColumns, int(index) / uTileColumns);
  const ivec2 size = imageSize(uIntensityImage);
  const ivec2 across = kAlong.yx;
  const ivec2 first = tile * kTile + int(gl_LocalInvocationID.x) * across + int(gl_LocalInvocationID.y) * kSegment * kAlong;
  const int start = first.x * kAlong.x + first.y * kAlong.y;  // along the line
  const int extent = size.x * kAlong.x + size.y * kAlong.y;
  const ivec2 line = first - start * kAlong;                    // the line's pixel 0
  const bool lineInside = all(lessThan(line, size));
  // Per pixel of the segment: its window [lo, hi] along the line (empty: nothing to write
  // or to add), its depth, and whether it is written at all (not where the fragment shader
  // discards: off the receivers).
  int lo[kSegment], hi[kSegment];
  float depth[kSegment], sum[kSegment], count[kSegment];
  bool writes[kSegment];
  int from = extent, to = -1;
  for (int k = 0; k < kSegment; ++k) {
    const int along = start + k;
    const ivec2 pixel = line + along * kAlong;
    Receiver r;
    writes[k] = lineInside && along < extent && loadReceiver(pixel, r);
    const vec2 centre = imageLoad(uIntensityImage, pixel).xy;
    depth[k] = centre.y;
    lo[k] = extent;
    hi[k] = -1;
    if (writes[k] && !(centre.y < 0.0)) {
      const int radius = filterRadius(r);
      lo[k] = along + max(-radius, -along);
      hi[k] = along + min(radius, extent - 1 - along);
      from = min(from, lo[k]);
      to = max(to, hi[k]);
    }
    sum[k] = 0.0;
    count[k] = 0.0;
  }
  for (int t = from; t <= to; ++t) {
    const vec2 tap = imageLoad(uIntensityImage, line + t * kAlong).xy;
    for (int k = 0; k < kSegment; ++k)
      if (t >= lo[k] && t <= hi[k] && filterTakes(depth[k], tap)) {
        sum[k] += tap.x;
        count[k] += 1.0;
      }
  }
  for (int k = 0; k < kSegment; ++k) {
    if (!writes[k]) continue;
    // Facing away (depth −1): (0, −1), as the fragment shader writes; count ≥ 1 otherwise.
    const vec2 v = depth[k] < 0.0 ? vec2(0.0, -1.0) : vec2(sum[k] / count[k], depth[k]);
    imageStore(uFiltered, line + (start + k) * kAlong, vec4(v, 0.0, 0.0));
  }
}
