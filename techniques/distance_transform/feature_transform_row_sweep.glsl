// Feature transform, pass 1 (feature_transform.h): one invocation per row writes, for each
// pixel, the column of the nearest seed in the same row, or -1 when the row has none. Two
// sweeps: the last seed to the left, then the next seed to the right, keeping the closer.
//
// The including shader defines, before including this file,
//   bool featureTransformIsSeed(ivec2 pixel)
// asked once for each pixel of the row, from the first column to the last; its main()
// calls featureTransformRow().
layout(local_size_x = 64) in;

uniform ivec2 uSize;
layout(std430, binding = 0) buffer RowNearest { int rowNearest[]; };

void featureTransformRow() {
  const int y = int(gl_GlobalInvocationID.x);
  if (y >= uSize.y) return;
  const int row = y * uSize.x;
  int left = -1;
  for (int x = 0; x < uSize.x; ++x) {
    if (featureTransformIsSeed(ivec2(x, y))) left = x;
    rowNearest[row + x] = left;
  }
  // Right to left: `right` is the next seed at or after x; it wins only when strictly
  // closer (a tie keeps the left one, either is exact). The first sweep left each seed's
  // own column at the seed, so the seeds need not be asked again.
  int right = -1;
  for (int x = uSize.x - 1; x >= 0; --x) {
    const int l = rowNearest[row + x];
    if (l == x) right = x;
    if (right < 0) continue;
    if (l < 0 || right - x < x - l) rowNearest[row + x] = right;
  }
}
