#include "testbed/metrics/distance_transform.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace testbed {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// 1D squared distance transform of a sampled function f (Felzenszwalb & Huttenlocher):
// out[q] = min_p ((q - p)^2 + f[p]). Infinite samples are skipped rather than entered as
// parabolas, because their intersections would be inf - inf = NaN. Every intersection is
// a ratio of integers with a denominator below 2n, so double rounding cannot reorder two
// distinct intersections or move one across an integer: the result is exact.
void envelope1d(const double* f, double* out, int n, std::vector<int>& v, std::vector<double>& z) {
  int k = -1;  // index of the rightmost parabola in the envelope
  for (int q = 0; q < n; ++q) {
    if (f[q] == kInf) continue;
    const double fq = f[q] + double(q) * q;
    double s = -kInf;
    while (k >= 0) {
      const int p = v[k];
      s = (fq - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s <= z[k]) --k;  // the new parabola hides parabola p entirely
      else break;
    }
    if (k < 0) s = -kInf;
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  if (k < 0) {  // no finite sample on this line
    for (int q = 0; q < n; ++q) out[q] = kInf;
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[j + 1] < q) ++j;
    const double d = q - v[j];
    out[q] = d * d + f[v[j]];
  }
}

}  // namespace

std::vector<double> squaredDistanceTransform(int width, int height, std::span<const std::uint8_t> seeds) {
  if (width < 0 || height < 0)
    throw std::invalid_argument("distance transform: negative size " + std::to_string(width) + "x" +
                                std::to_string(height));
  const std::size_t count = std::size_t(width) * std::size_t(height);
  if (seeds.size() != count)
    throw std::invalid_argument("distance transform: " + std::to_string(seeds.size()) + " seeds for a " +
                                std::to_string(width) + "x" + std::to_string(height) + " grid");
  std::vector<double> g(count);
  if (count == 0) return g;

  // Column pass: distance to the nearest seed in the same column, as a forward and a
  // backward sweep done row by row so that memory is walked in order.
  for (int x = 0; x < width; ++x) g[x] = seeds[x] ? 0.0 : kInf;
  for (int y = 1; y < height; ++y) {
    const std::size_t row = std::size_t(y) * width;
    for (int x = 0; x < width; ++x) g[row + x] = seeds[row + x] ? 0.0 : g[row - width + x] + 1.0;
  }
  for (int y = height - 2; y >= 0; --y) {
    const std::size_t row = std::size_t(y) * width;
    for (int x = 0; x < width; ++x) {
      const double below = g[row + width + x] + 1.0;
      if (below < g[row + x]) g[row + x] = below;
    }
  }

  // Row pass: lower envelope of parabolas centred on each column with height g^2.
  std::vector<double> f(width), out(count);
  std::vector<int> v(width);
  std::vector<double> z(std::size_t(width) + 1);
  for (int y = 0; y < height; ++y) {
    const std::size_t row = std::size_t(y) * width;
    for (int x = 0; x < width; ++x) f[x] = g[row + x] * g[row + x];
    envelope1d(f.data(), out.data() + row, width, v, z);
  }
  return out;
}

}  // namespace testbed
