// The GPU feature transforms against a brute-force CPU nearest-seed search: for every pixel
// the returned coordinate must be a seed and its squared distance must equal the exact
// minimum. The banded transform (PBA's shape) must moreover return the two-pass one's seed
// exactly, the least (distance², row, column), which EDTSM's bit-identical paths rely on, at
// any band width.
#include "techniques/distance_transform/feature_transform.h"
#include "techniques/distance_transform/feature_transform_banded.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "testbed/core/error.h"
#include "testbed/gl/pass_timer.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

struct Mask {
  int width = 0, height = 0;
  std::vector<std::uint8_t> seed;  // texel (x, y) at y * width + x
  bool at(int x, int y) const { return seed[std::size_t(y) * width + x] != 0; }
};

Mask randomMask(int width, int height, double density, unsigned salt) {
  Mask m{width, height, std::vector<std::uint8_t>(std::size_t(width) * height)};
  std::mt19937 rng(1234u + salt * 7919u + unsigned(width) * 31u + unsigned(height));
  std::bernoulli_distribution isSeed(density);
  for (auto& s : m.seed) s = isSeed(rng) ? 1 : 0;
  return m;
}

// Squared distance to the nearest seed (-1 if none), by brute force: rows are visited in
// order of |dy| and every seed of a row is tried, stopping once dy² alone reaches the best.
std::vector<std::int64_t> bruteForce(const Mask& m) {
  std::vector<std::vector<int>> seedsOfRow(m.height);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (m.at(x, y)) seedsOfRow[y].push_back(x);
  std::vector<std::int64_t> best(std::size_t(m.width) * m.height, -1);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      std::int64_t d2 = std::numeric_limits<std::int64_t>::max();
      for (int dy = 0; dy < m.height && std::int64_t(dy) * dy < d2; ++dy)
        for (const int row : {y - dy, y + dy}) {
          if (row < 0 || row >= m.height || (dy == 0 && row != y)) continue;
          for (const int sx : seedsOfRow[row]) d2 = std::min(d2, std::int64_t(sx - x) * (sx - x) + std::int64_t(dy) * dy);
        }
      if (d2 != std::numeric_limits<std::int64_t>::max()) best[std::size_t(y) * m.width + x] = d2;
    }
  return best;
}

Texture upload(const Mask& m, GLenum format) {
  Texture t = Texture::create2D(format, m.width, m.height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (format == GL_R8) {
    std::vector<std::uint8_t> texels(m.seed.size());
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = m.seed[i] ? 255 : 0;
    glTextureSubImage2D(t.id(), 0, 0, 0, m.width, m.height, GL_RED, GL_UNSIGNED_BYTE, texels.data());
  } else {
    // Exactly 0.5 is not a seed: the threshold is strict.
    std::vector<float> texels(m.seed.size());
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = m.seed[i] ? 0.5001f : 0.5f;
    glTextureSubImage2D(t.id(), 0, 0, 0, m.width, m.height, GL_RED, GL_FLOAT, texels.data());
  }
  return t;
}

// The least (distance², row, column) seed of every pixel, (-1, -1) without seeds.
std::vector<glm::ivec2> bruteForceSeed(const Mask& m) {
  std::vector<glm::ivec2> seeds;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      if (m.at(x, y)) seeds.push_back({x, y});  // in (row, column) order
  std::vector<glm::ivec2> best(std::size_t(m.width) * m.height, glm::ivec2(-1));
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      std::int64_t d2 = std::numeric_limits<std::int64_t>::max();
      for (const glm::ivec2 s : seeds) {
        const std::int64_t d = std::int64_t(s.x - x) * (s.x - x) + std::int64_t(s.y - y) * (s.y - y);
        if (d < d2) d2 = d, best[std::size_t(y) * m.width + x] = s;  // strict: the first in order keeps a tie
      }
    }
  return best;
}

// Runs `pass` on the mask and checks every pixel; returns the number of wrong pixels.
template <class Pass>
int checkAgainstBruteForce(Pass& pass, const Mask& m, GLenum format = GL_R8) {
  const Texture seeds = upload(m, format);
  pass.run(seeds, {m.width, m.height});
  const std::vector<glm::ivec2> nearest = pass.readNearest();
  const std::vector<std::int64_t> expected = bruteForce(m);
  int wrong = 0;
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x) {
      const std::size_t i = std::size_t(y) * m.width + x;
      const glm::ivec2 n = nearest[i];
      bool ok;
      if (expected[i] < 0) {
        ok = n == glm::ivec2(-1);
      } else {
        ok = n.x >= 0 && n.y >= 0 && n.x < m.width && n.y < m.height && m.at(n.x, n.y) &&
             std::int64_t(n.x - x) * (n.x - x) + std::int64_t(n.y - y) * (n.y - y) == expected[i];
      }
      if (!ok && ++wrong <= 5)
        ADD_FAILURE() << m.width << "x" << m.height << " pixel (" << x << ", " << y << "): got (" << n.x
                      << ", " << n.y << "), expected squared distance " << expected[i];
    }
  return wrong;
}

class FeatureTransform : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
  FeatureTransformPass pass_;
};

TEST_F(FeatureTransform, RandomMasksMatchBruteForceAtEverySizeAndDensity) {
  const glm::ivec2 sizes[] = {{1, 1}, {1, 37}, {53, 1}, {97, 61}, {320, 180}};
  const double densities[] = {0.0005, 0.01, 0.3, 1.0};
  unsigned salt = 0;
  // One pass object for all of them: resizing must reallocate and stay exact.
  for (const glm::ivec2 size : sizes)
    for (const double density : densities)
      for (const GLenum format : {GL_R8, GL_R32F}) {
        SCOPED_TRACE(std::to_string(size.x) + "x" + std::to_string(size.y) + " density " +
                     std::to_string(density) + (format == GL_R8 ? " R8" : " R32F"));
        EXPECT_EQ(checkAgainstBruteForce(pass_, randomMask(size.x, size.y, density, ++salt), format), 0);
      }
}

TEST_F(FeatureTransform, SingleSeedAnywhere) {
  for (const glm::ivec2 seed : {glm::ivec2(0, 0), glm::ivec2(96, 60), glm::ivec2(96, 0), glm::ivec2(40, 17)}) {
    Mask m = randomMask(97, 61, 0.0, 0);
    m.seed[std::size_t(seed.y) * m.width + seed.x] = 1;
    EXPECT_EQ(checkAgainstBruteForce(pass_, m), 0) << "seed at " << seed.x << ", " << seed.y;
    const auto nearest = pass_.readNearest();
    for (const glm::ivec2 n : nearest) ASSERT_EQ(n, seed);
  }
}

TEST_F(FeatureTransform, NoSeedGivesMinusOneEverywhere) {
  for (const glm::ivec2 size : {glm::ivec2(1, 1), glm::ivec2(1, 37), glm::ivec2(53, 1), glm::ivec2(320, 180)}) {
    const Mask m = randomMask(size.x, size.y, 0.0, 0);
    pass_.run(upload(m, GL_R32F), size);
    for (const glm::ivec2 n : pass_.readNearest()) ASSERT_EQ(n, glm::ivec2(-1));
  }
}

// Rows without a seed between seeded rows, and equidistant seeds (ties) everywhere: a grid
// of seeds every 8 columns on every 6th row, plus a shadow-boundary-like circle outline.
TEST_F(FeatureTransform, StructuredMasksWithEmptyRowsAndTies) {
  Mask grid = randomMask(320, 180, 0.0, 0);
  for (int y = 3; y < grid.height; y += 6)
    for (int x = 0; x < grid.width; x += 8) grid.seed[std::size_t(y) * grid.width + x] = 1;
  EXPECT_EQ(checkAgainstBruteForce(pass_, grid), 0);
  Mask circle = randomMask(320, 180, 0.0, 0);
  for (int y = 0; y < circle.height; ++y)
    for (int x = 0; x < circle.width; ++x) {
      const int r2 = (x - 150) * (x - 150) + (y - 80) * (y - 80);
      circle.seed[std::size_t(y) * circle.width + x] = r2 >= 60 * 60 && r2 < 61 * 61;
    }
  EXPECT_EQ(checkAgainstBruteForce(pass_, circle), 0);
}

TEST_F(FeatureTransform, FullHdSparseSeeds) {
  const auto start = std::chrono::steady_clock::now();
  const Mask m = randomMask(1280, 720, 0.0005, 99);
  const Texture seeds = upload(m, GL_R8);
  pass_.run(seeds, {1280, 720});  // warm-up: compiles nothing new, allocates
  glFinish();
  const auto gpuStart = std::chrono::steady_clock::now();
  pass_.run(seeds, {1280, 720});
  glFinish();
  const double gpuMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - gpuStart).count();
  EXPECT_EQ(checkAgainstBruteForce(pass_, m), 0);
  std::printf("1280x720 feature transform: %.1f ms on this backend (test total %.0f ms)\n", gpuMs,
              std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
}

// Only texels [0, size) of a larger seed texture are read.
TEST_F(FeatureTransform, ReadsOnlyTheRequestedRegion) {
  Mask big = randomMask(64, 64, 0.0, 0);
  big.seed[std::size_t(50) * 64 + 50] = 1;  // outside the 40x30 region
  big.seed[std::size_t(5) * 64 + 7] = 1;
  const Texture seeds = upload(big, GL_R8);
  pass_.run(seeds, {40, 30});
  for (const glm::ivec2 n : pass_.readNearest()) ASSERT_EQ(n, glm::ivec2(7, 5));
}

TEST_F(FeatureTransform, OutputAndScratchAreBookedInTheLedger) {
  const Texture seeds = upload(randomMask(97, 61, 0.01, 3), GL_R8);
  GpuMemoryLedger ledger;
  {
    GpuMemoryLedger::Scope booking(ledger);
    FeatureTransformPass pass;
    pass.run(seeds, {97, 61});
    // RG32I output (8 bytes), row pass result (4) and the envelope stack (8) per pixel.
    EXPECT_EQ(pass.nearest().bytes(), 97u * 61u * 8u);
    EXPECT_EQ(ledger.bytes(), 97u * 61u * 20u);
    pass.run(seeds, {97, 61});  // same size: nothing new
    EXPECT_EQ(ledger.bytes(), 97u * 61u * 20u);
    pass.run(seeds, {50, 40});  // resized: the old allocations are returned
    EXPECT_EQ(ledger.bytes(), 50u * 40u * 20u);
  }
  EXPECT_EQ(ledger.bytes(), 0u);
}

// Every band width, including one pixel, one wider than the image and widths that leave a
// partial band; sizes with one row or column; densities from none to every pixel. The
// brute-force least (distance², row, column) seed is the expected answer of both transforms.
TEST_F(FeatureTransform, BandedReturnsTheTwoPassSeedAndTheLeastTiedOne) {
  const glm::ivec2 sizes[] = {{1, 1}, {1, 37}, {53, 1}, {97, 61}, {160, 90}};
  const double densities[] = {0.0, 0.0005, 0.01, 0.3, 1.0};
  std::vector<BandedFeatureTransformPass> banded;
  for (const int band : {1, 3, 8, 64, 200}) banded.emplace_back(band);
  unsigned salt = 500;
  for (const glm::ivec2 size : sizes)
    for (const double density : densities) {
      const Mask m = randomMask(size.x, size.y, density, ++salt);
      const Texture seeds = upload(m, GL_R8);
      const std::vector<glm::ivec2> expected = bruteForceSeed(m);
      pass_.run(seeds, size);
      const auto mismatches = [&](const std::vector<glm::ivec2>& got) {
        int n = 0;
        for (std::size_t i = 0; i < got.size(); ++i) n += got[i] != expected[i];
        return n;
      };
      const std::string where = std::to_string(size.x) + "x" + std::to_string(size.y) + " density " + std::to_string(density);
      EXPECT_EQ(mismatches(pass_.readNearest()), 0) << where << " two-pass";
      for (auto& b : banded) {
        b.run(seeds, size);
        EXPECT_EQ(mismatches(b.readNearest()), 0) << where << " banded, band " << (&b - banded.data());
      }
    }
}

// Ties everywhere (a seed grid), a circle outline and a single seed in a far corner.
TEST_F(FeatureTransform, BandedStructuredMasks) {
  BandedFeatureTransformPass banded;
  Mask grid = randomMask(320, 180, 0.0, 0);
  for (int y = 3; y < grid.height; y += 6)
    for (int x = 0; x < grid.width; x += 8) grid.seed[std::size_t(y) * grid.width + x] = 1;
  Mask circle = randomMask(320, 180, 0.0, 0);
  for (int y = 0; y < circle.height; ++y)
    for (int x = 0; x < circle.width; ++x) {
      const int r2 = (x - 150) * (x - 150) + (y - 80) * (y - 80);
      circle.seed[std::size_t(y) * circle.width + x] = r2 >= 60 * 60 && r2 < 61 * 61;
    }
  Mask corner = randomMask(640, 360, 0.0, 0);
  corner.seed[std::size_t(359) * 640 + 639] = 1;
  for (const Mask* m : {&grid, &circle, &corner}) {
    EXPECT_EQ(checkAgainstBruteForce(banded, *m), 0);
    checkAgainstBruteForce(pass_, *m);
    EXPECT_TRUE(banded.readNearest() == pass_.readNearest());
  }
}

// The point of the banded shape: at 1280×720 each phase dispatches at least 64 k
// invocations (counted by the GL's pipeline statistics), where the two-pass transform
// dispatches one a row, then one a column.
TEST_F(FeatureTransform, BandedDispatchesSixtyFourThousandInvocationsAPhase) {
  if (!workCountersAvailable()) GTEST_SKIP() << "no pipeline statistics on this GL";
  const Texture seeds = upload(randomMask(1280, 720, 0.0005, 7), GL_R8);
  GLuint query = 0;
  glGenQueries(1, &query);
  const auto count = [&] {
    glEndQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB);
    GLuint64 n = 0;
    glGetQueryObjectui64v(query, GL_QUERY_RESULT, &n);
    return n;
  };
  BandedFeatureTransformPass banded;
  std::vector<GLuint64> phases;
  glBeginQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB, query);
  banded.run(seeds, {1280, 720}, [&](int phase) {
    phases.push_back(count());
    if (phase < 3) glBeginQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB, query);
  });
  glBeginQuery(GL_COMPUTE_SHADER_INVOCATIONS_ARB, query);
  pass_.run(seeds, {1280, 720});
  const GLuint64 twoPass = count();
  glDeleteQueries(1, &query);
  ASSERT_EQ(phases.size(), 3u);
  std::printf("1280x720 compute invocations: banded phases %llu, %llu, %llu; two-pass total %llu\n",
              (unsigned long long)phases[0], (unsigned long long)phases[1], (unsigned long long)phases[2],
              (unsigned long long)twoPass);
  for (const GLuint64 n : phases) EXPECT_GE(n, 65536u);
  EXPECT_LT(twoPass, 65536u / 16u);  // 64-wide groups over 720 rows and 1280 columns
}

TEST_F(FeatureTransform, BandedBooksItsImagesAndRejectsBadSizes) {
  const Texture seeds = upload(randomMask(97, 61, 0.01, 3), GL_R8);
  GpuMemoryLedger ledger;
  {
    GpuMemoryLedger::Scope booking(ledger);
    BandedFeatureTransformPass pass(8);
    pass.run(seeds, {97, 61});
    // Per pixel: the RG32I output and links (8 bytes each), the row pass's R32I (4); per
    // row band (13 × 61): two RG32I; per column band (97 × 8): an RG32I and an R32I.
    const std::size_t expected = 97u * 61u * 20u + 13u * 61u * 16u + 97u * 8u * 12u;
    EXPECT_EQ(ledger.bytes(), expected);
    pass.run(seeds, {97, 61});
    EXPECT_EQ(ledger.bytes(), expected);
  }
  EXPECT_EQ(ledger.bytes(), 0u);
  BandedFeatureTransformPass pass;
  EXPECT_THROW(pass.run(seeds, {0, 8}), GlError);
  EXPECT_THROW(pass.run(seeds, {98, 8}), GlError);
  EXPECT_THROW(BandedFeatureTransformPass(0), GlError);
}

TEST_F(FeatureTransform, RejectsBadSizes) {
  const Texture seeds = upload(randomMask(8, 8, 0.5, 1), GL_R8);
  EXPECT_THROW(pass_.run(seeds, {0, 8}), GlError);
  EXPECT_THROW(pass_.run(seeds, {9, 8}), GlError);
}

}  // namespace
}  // namespace testbed
