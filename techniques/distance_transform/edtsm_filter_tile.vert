#version 450 core
// One tile of the screen per instance (edtsm_filter_tiles.h), drawn as two triangles when
// some pixel of it can see, within the mean filter's largest window, receivers of more
// than one kind or of a kind other than 0 and 1; a point off the screen otherwise.
uniform usampler2D uTileKinds;  // per tile: bit 0 a receiver at 0, bit 1 at 1, bit 2 other
uniform ivec2 uTileReach;       // tiles to each side that the window can reach, along x and y
uniform ivec2 uScreenSize;

const int kTile = 32;

void main() {
  const ivec2 tiles = textureSize(uTileKinds, 0);
  const ivec2 tile = ivec2(gl_InstanceID % tiles.x, gl_InstanceID / tiles.x);
  uint kinds = 0u;
  for (int dy = -uTileReach.y; dy <= uTileReach.y; ++dy)
    for (int dx = -uTileReach.x; dx <= uTileReach.x; ++dx) {
      const ivec2 t = tile + ivec2(dx, dy);
      if (all(greaterThanEqual(t, ivec2(0))) && all(lessThan(t, tiles))) kinds |= texelFetch(uTileKinds, t, 0).r;
    }
  if (kinds == 0u || kinds == 1u || kinds == 2u) {  // the filter keeps every pixel's value
    gl_Position = vec4(2.0, 2.0, 0.0, 1.0);
    return;
  }
  const ivec2 corners[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1), ivec2(0, 1), ivec2(1, 0), ivec2(1, 1));
  const ivec2 pixel = min((tile + corners[gl_VertexID]) * kTile, uScreenSize);
  gl_Position = vec4(vec2(pixel) / vec2(uScreenSize) * 2.0 - 1.0, 0.0, 1.0);
}
