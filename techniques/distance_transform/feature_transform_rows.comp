#version 450 core
// Feature transform, pass 1 (feature_transform.h): one invocation per row writes, for each
// pixel, the column of the nearest seed in the same row, or -1 when the row has none. Two
// sweeps: the last seed to the left, then the next seed to the right, keeping the closer.
layout(local_size_x = 64) in;

uniform sampler2D uSeeds;
uniform ivec2 uSize;
layout(std430, binding = 0) buffer RowNearest { int rowNearest[]; };

bool isSeed(int x, int y) { return texelFetch(uSeeds, ivec2(x, y), 0).r > 0.5; }

void main() {
  const int y = int(gl_GlobalInvocationID.x);
  if (y >= uSize.y) return;
  const int row = y * uSize.x;
  int left = -1;
  for (int x = 0; x < uSize.x; ++x) {
    if (isSeed(x, y)) left = x;
    rowNearest[row + x] = left;
  }
  // Right to left: `right` is the next seed at or after x; it wins only when strictly
  // closer (a tie keeps the left one, either is exact).
  int right = -1;
  for (int x = uSize.x - 1; x >= 0; --x) {
    if (isSeed(x, y)) right = x;
    if (right < 0) continue;
    const int l = rowNearest[row + x];
    if (l < 0 || right - x < x - l) rowNearest[row + x] = right;
  }
}
