#version 450 core
// Banded feature transform, phase 1 (feature_transform_banded.h): per row, the nearest
// seed column of each pixel, ties to the left. The row is cut into bands of uBand columns;
// STEP 1: each band (one invocation) finds its first and last seed; STEP 2: one invocation
// a row carries the nearest seeds across the bands (the last seed left of each band, the
// first right of it); STEP 3: each band sweeps its pixels left to right, then right to
// left, starting from what was carried in.
#include "techniques/distance_transform/feature_transform_band.glsl"

uniform sampler2D uSeeds;  // a seed where red > 0.5
layout(rg32i, binding = kBandSeedsImageUnit) uniform iimage2D uBandSeeds;
layout(rg32i, binding = kBandCarryImageUnit) uniform iimage2D uBandCarry;
layout(r32i, binding = kBandRowNearestImageUnit) uniform iimage2D uRowNearest;

bool isSeed(int x, int y) { return texelFetch(uSeeds, ivec2(x, y), 0).r > 0.5; }

void main() {
  const int bands = (uSize.x + uBand - 1) / uBand;
#if STEP == 2
  const int y = int(gl_WorkGroupID.x * 64u + gl_LocalInvocationIndex);  // 64 rows a group
  if (y >= uSize.y) return;
  int left = -1;
  for (int band = 0; band < bands; ++band) {
    const ivec2 seeds = imageLoad(uBandSeeds, ivec2(band, y)).xy;
    imageStore(uBandCarry, ivec2(band, y), ivec4(left, 0, 0, 0));
    if (seeds.y >= 0) left = seeds.y;
  }
  int right = -1;
  for (int band = bands - 1; band >= 0; --band) {
    const int carriedLeft = imageLoad(uBandCarry, ivec2(band, y)).x;
    imageStore(uBandCarry, ivec2(band, y), ivec4(carriedLeft, right, 0, 0));
    const int first = imageLoad(uBandSeeds, ivec2(band, y)).x;
    if (first >= 0) right = first;
  }
#else
  const int band = int(gl_GlobalInvocationID.x), y = int(gl_GlobalInvocationID.y);
  if (band >= bands || y >= uSize.y) return;
  const int from = band * uBand, to = min(from + uBand, uSize.x);
#if STEP == 1
  int first = -1, last = -1;
  for (int x = from; x < to; ++x)
    if (isSeed(x, y)) {
      if (first < 0) first = x;
      last = x;
    }
  imageStore(uBandSeeds, ivec2(band, y), ivec4(first, last, 0, 0));
#else
  const ivec2 carried = imageLoad(uBandCarry, ivec2(band, y)).xy;
  int left = carried.x;
  for (int x = from; x < to; ++x) {
    if (isSeed(x, y)) left = x;
    imageStore(uRowNearest, ivec2(x, y), ivec4(left));
  }
  // Right to left: the next seed at or after x wins only when strictly closer.
  int right = carried.y;
  for (int x = to - 1; x >= from; --x) {
    const int l = imageLoad(uRowNearest, ivec2(x, y)).x;
    if (l == x) right = x;
    if (right >= 0 && (l < 0 || right - x < x - l)) imageStore(uRowNearest, ivec2(x, y), ivec4(right));
  }
#endif
#endif
}
