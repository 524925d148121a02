#version 450 core
// The runs of tile rows where EDTSM's eq. 8 can change a pixel, one invocation per tile
// column (edtsm_penumbra_band.h): per tile, R from its least receiver depth; the tile is
// needed when a tile with a seed lies within ceil(R / kBandTile) tiles; consecutive needed
// tiles make one run, with the largest R of its tiles.
#include "testbed/glsl/units.glsl"
#include "techniques/distance_transform/edtsm_tiles.glsl"

layout(local_size_x = 64) in;

uniform ivec2 uSize;            // pixels
layout(r32ui, binding = kTileSeedsImageUnit) uniform readonly uimage2D uTileSeeds;     // 1: the tile holds a seed
layout(r32ui, binding = kTileMinDepthImageUnit) uniform readonly uimage2D uTileMinDepth;  // least receiver depth, bits; ~0: none
uniform float uHalfPenumbra;    // P/2 with a margin for rounding; <= 0: no penumbra anywhere
uniform float uBandScale;       // F · k · P/2 with a margin (edtsm_penumbra_band.h)
uniform vec2 uDepthToEye;       // (projection[3][2], projection[2][2]): Z = x / (z_ndc + y)
// Per tile column, entry 0: (number of runs, 0, 0, 0); then (first row, end row, R, 0).
layout(std430, binding = kPenumbraRunsBufferBinding) writeonly buffer Runs { ivec4 runs[]; };

// R of a tile (edtsm_penumbra_band.h), -1 without receivers.
int bandRadius(ivec2 tile) {
  const uint bits = imageLoad(uTileMinDepth, tile).r;
  const int unbounded = uSize.x + uSize.y;
  if (bits == 0xFFFFFFFFu) return -1;
  // The stored depth is rounded: take it 1e-5 nearer, and the eye depth 0.1 % nearer still.
  const float zNdc = 2.0 * (uintBitsToFloat(bits) - 1e-5) - 1.0;
  const float nearest = 0.999 * uDepthToEye.x / (zNdc + uDepthToEye.y) - uHalfPenumbra;
  if (!(nearest > 0.0)) return unbounded;
  return int(min(ceil(uBandScale / nearest) + 2.0, float(unbounded)));
}

bool holdsSeedWithin(ivec2 tile, int reach, ivec2 tiles) {
  const ivec2 first = max(tile - reach, ivec2(0)), last = min(tile + reach, tiles - 1);
  bool seed = false;
  for (int y = first.y; y <= last.y; ++y)
    for (int x = first.x; x <= last.x; ++x) seed = seed || imageLoad(uTileSeeds, ivec2(x, y)).r != 0u;
  return seed;
}

void main() {
  const ivec2 tiles = imageSize(uTileSeeds);
  const int column = int(gl_GlobalInvocationID.x);
  if (column >= tiles.x) return;
  const int base = column * (tiles.y + 1);
  int count = 0, runRadius = -1;
  for (int row = 0; row <= tiles.y; ++row) {
    int radius = -1;
    if (row < tiles.y && uHalfPenumbra > 0.0) {
      radius = bandRadius(ivec2(column, row));
      if (radius >= 0 && !holdsSeedWithin(ivec2(column, row), (radius + kBandTile - 1) / kBandTile, tiles)) radius = -1;
    }
    if (radius >= 0) {
      if (runRadius < 0) runs[base + 1 + count].x = row * kBandTile;  // a run starts
      runRadius = max(runRadius, radius);
    } else if (runRadius >= 0) {  // a run ends before this row
      runs[base + 1 + count].yz = ivec2(min(row * kBandTile, uSize.y), runRadius);
      ++count;
      runRadius = -1;
    }
  }
  runs[base] = ivec4(count, 0, 0, 0);
}
