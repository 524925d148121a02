#version 450 core
// The lists of tiles the mean filter's two dispatches run on (edtsm_filter_tiles.h), one
// invocation per tile: a tile is listed for a direction when some pixel of it can see,
// within the filter's largest window along that direction's reach, receivers of more than
// one kind or of a kind other than 0 and 1.
layout(local_size_x = 64) in;

uniform usampler2D uTileKinds;  // per tile: bit 0 a receiver at 0, bit 1 at 1, bit 2 other
uniform ivec2 uRowReach;        // tiles to each side the first (row) window reaches
uniform ivec2 uColumnReach;     // and the second's (the box both windows make)
uniform int uListLength;        // tiles, the capacity of each list
// (x, y, z) indirect dispatch arguments of the row list, then of the column list, then the
// row list's tiles and the column list's, x + y · tiles.x each.
#include "testbed/glsl/units.glsl"
layout(std430, binding = kTileListBufferBinding) buffer Tiles { uint tileList[]; };

bool changes(ivec2 tile, ivec2 reach, ivec2 tiles) {
  uint kinds = 0u;
  for (int dy = -reach.y; dy <= reach.y; ++dy)
    for (int dx = -reach.x; dx <= reach.x; ++dx) {
      const ivec2 t = tile + ivec2(dx, dy);
      if (all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, tiles))) kinds |= texelFetch(uTileKinds, t, 0).r;
    }
  return !(kinds == 0u || kinds == 1u || kinds == 2u);  // else the filter keeps every pixel's value
}

void main() {
  const ivec2 tiles = textureSize(uTileKinds, 0);
  const int index = int(gl_GlobalInvocationID.x);
  if (index >= tiles.x * tiles.y) return;
  const ivec2 tile = ivec2(index % tiles.x, index / tiles.x);
  if (changes(tile, uRowReach, tiles)) tileList[6 + atomicAdd(tileList[0], 1u)] = uint(index);
  if (changes(tile, uColumnReach, tiles)) tileList[6 + uListLength + atomicAdd(tileList[3], 1u)] = uint(index);
}
