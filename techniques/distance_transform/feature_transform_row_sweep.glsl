// Feature transform, pass 1 (feature_transform.h): one invocation per row writes, for each
// pixel, the column of the nearest seed in the same row, or -1 when the row has none. Two
// sweeps: the last seed to the left, then the next seed to the right, keeping the closer.
//
// The including shader defines, before including this file,
//   const int kRowSpan                         pixels between two featureTransformSpanEnd()
//   void featureTransformRowBegin(int y)       before row y's first featureTransformIsSeed()
//   bool featureTransformIsSeed(ivec2 pixel)   asked once for each pixel of the row, from the
//                                              first column to the last
//   void featureTransformSpanEnd(ivec2 pixel)  after the pixel of each kRowSpan-th column and
//                                              after the row's last one
// and its main() calls featureTransformRow(). The hooks let a shader keep per-row work out
// of the per-pixel loop: llvmpipe runs a branch's body for all 8 lanes of a vector, taken
// or not, so work behind an `if` in the loop is paid at every pixel.
#include "testbed/glsl/units.glsl"

layout(local_size_x = 64) in;

uniform ivec2 uSize;
// An image, not a buffer: llvmpipe stores to an image for about half the instructions of
// a store to a buffer (feature_transform.h).
layout(r32i, binding = kRowNearestImageUnit) uniform iimage2D uRowNearest;

void featureTransformRow() {
  const int y = int(gl_GlobalInvocationID.x);
  if (y >= uSize.y) return;
  featureTransformRowBegin(y);
  int left = -1;
  for (int spanStart = 0; spanStart < uSize.x; spanStart += kRowSpan) {
    const int spanEnd = min(spanStart + kRowSpan, uSize.x);
    for (int x = spanStart; x < spanEnd; ++x) {
      if (featureTransformIsSeed(ivec2(x, y))) left = x;
      imageStore(uRowNearest, ivec2(x, y), ivec4(left));
    }
    featureTransformSpanEnd(ivec2(spanEnd - 1, y));
  }
  // Right to left: `right` is the next seed at or after x; it wins only when strictly
  // closer (a tie keeps the left one, either is exact). The first sweep left each seed's
  // own column at the seed, so the seeds need not be asked again.
  int right = -1;
  for (int x = uSize.x - 1; x >= 0; --x) {
    const int l = imageLoad(uRowNearest, ivec2(x, y)).x;
    if (l == x) right = x;
    if (right < 0) continue;
    if (l < 0 || right - x < x - l) imageStore(uRowNearest, ivec2(x, y), ivec4(right));
  }
}
