// The separable distance transform must equal brute force exactly: squared distances are
// integers, so any envelope or rounding slip shows up as an inequality.
#include "testbed/metrics/distance_transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace testbed {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// O(pixels x seeds) reference: the definition itself.
std::vector<double> bruteForce(int w, int h, const std::vector<std::uint8_t>& seeds) {
  std::vector<double> out(std::size_t(w) * h, kInf);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int sy = 0; sy < h; ++sy)
        for (int sx = 0; sx < w; ++sx)
          if (seeds[std::size_t(sy) * w + sx]) {
            const double d = double(x - sx) * (x - sx) + double(y - sy) * (y - sy);
            double& o = out[std::size_t(y) * w + x];
            if (d < o) o = d;
          }
  return out;
}

std::vector<std::uint8_t> randomSeeds(int w, int h, double density, unsigned seed) {
  std::mt19937 rng(seed);
  std::bernoulli_distribution coin(density);
  std::vector<std::uint8_t> s(std::size_t(w) * h);
  for (auto& v : s) v = coin(rng) ? 1 : 0;
  return s;
}

void expectMatchesBruteForce(int w, int h, const std::vector<std::uint8_t>& seeds) {
  const auto fast = squaredDistanceTransform(w, h, seeds);
  const auto slow = bruteForce(w, h, seeds);
  ASSERT_EQ(fast.size(), slow.size());
  for (std::size_t i = 0; i < fast.size(); ++i)
    ASSERT_EQ(fast[i], slow[i]) << w << "x" << h << " pixel (" << i % w << ", " << i / w << ")";
}

TEST(DistanceTransform, MatchesBruteForceOnRandomMasks) {
  const int sizes[][2] = {{1, 1}, {1, 17}, {23, 1}, {37, 23}, {64, 64}, {5, 40}};
  const double densities[] = {0.002, 0.02, 0.3, 0.9, 1.0};
  unsigned seed = 1;
  for (const auto& size : sizes)
    for (double density : densities)
      for (int repeat = 0; repeat < 3; ++repeat)
        expectMatchesBruteForce(size[0], size[1], randomSeeds(size[0], size[1], density, seed++));
}

TEST(DistanceTransform, SingleSeedAtEachCorner) {
  const int w = 37, h = 23;
  const int corners[][2] = {{0, 0}, {w - 1, 0}, {0, h - 1}, {w - 1, h - 1}};
  for (const auto& c : corners) {
    std::vector<std::uint8_t> seeds(std::size_t(w) * h, 0);
    seeds[std::size_t(c[1]) * w + c[0]] = 1;
    const auto d = squaredDistanceTransform(w, h, seeds);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        ASSERT_EQ(d[std::size_t(y) * w + x], double((x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1])));
  }
  expectMatchesBruteForce(1, 1, {1});
}

TEST(DistanceTransform, NoSeedIsInfinity) {
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{1, 9}, std::pair{9, 1}, std::pair{37, 23}}) {
    const auto d = squaredDistanceTransform(w, h, std::vector<std::uint8_t>(std::size_t(w) * h, 0));
    ASSERT_EQ(d.size(), std::size_t(w) * h);
    for (double v : d) EXPECT_EQ(v, kInf);
  }
}

TEST(DistanceTransform, SeedsOnlyInSomeRowsAndColumns) {
  // Rows and columns without any seed exercise the infinite samples of both passes.
  const int w = 30, h = 20;
  std::vector<std::uint8_t> seeds(std::size_t(w) * h, 0);
  seeds[std::size_t(4) * w + 7] = 1;
  seeds[std::size_t(15) * w + 25] = 1;
  expectMatchesBruteForce(w, h, seeds);
  const auto d = squaredDistanceTransform(w, h, seeds);
  EXPECT_EQ(d[0], 7.0 * 7 + 4 * 4);
  EXPECT_EQ(d[std::size_t(19) * w + 29], 4.0 * 4 + 4 * 4);
}

TEST(DistanceTransform, EmptyGridAndBadSizes) {
  EXPECT_TRUE(squaredDistanceTransform(0, 5, {}).empty());
  EXPECT_THROW(squaredDistanceTransform(3, 3, std::vector<std::uint8_t>(8)), std::invalid_argument);
  EXPECT_THROW(squaredDistanceTransform(-1, 3, {}), std::invalid_argument);
}

}  // namespace
}  // namespace testbed
