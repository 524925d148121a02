// Unit tests of the revectorization GLSL itself (not a C++ copy): probe.comp includes the
// family's shader files and evaluates a visibility function for a list of light-space
// samples against a synthetic 32×32 R32F "shadow map" (nearest, clamp to border 0 like
// the real one). Occluder texels store depth 0.2, receiver texels 0.5, samples lie at
// depth 0.5, so s = 1 exactly where the texel centre is off the occluder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "techniques/revectorization/rpcf_tiles.h"
#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/glsl/units.h"
#include "testbed/render/depth_image.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

constexpr int kSize = 32;
constexpr int kPerTexel = 8;  // samples per texel side
constexpr float kOccluder = 0.2f, kReceiver = 0.5f;

enum Function {
  kShadowTest = 0, kSmsr = 1, kRsmss = 2, kRpcfSmsr = 3, kRpcfRsmss = 4,
  kRpcfSmsrScreen = 5, kRpcfRsmssScreen = 6,  // as the screen pass computes them
  kClassify = 7, kClassifyFetched = 8,         // rvClassify's s, d, edge (packed), two ways
  kBlockRow = 9, kFetchedRow = 10,             // RPCF's row masks (packed), two ways
  kRegularBlock = 11, kRegularBlockPlain = 12, // RPCF's block check, two ways
};

struct Options {
  bool improved = false;
  int maxSearch = 16;
  int kernel = 1;
  int row = 0;  // kBlockRow, kFetchedRow: the block's row 0 … k + 1
};

// occluded(x, y) in texel units (x, y continuous): the analytic occluder.
using Shape = std::function<bool(double, double)>;

class Probe {
 public:
  // `layout`: where rvStoredDepth reads (depth_image.h).
  explicit Probe(int size = kSize, DepthImage::Layout layout = DepthImage::Layout::Blocks)
      : size_(size) {
    test::sharedContext();
    tiles_.emplace();
    depthImage_.emplace();
    depthImage_->setLayout(layout);
    program_ = Program::compute("techniques/revectorization/probe.comp", depthImage_->defines());
    map_ = Texture::create2D(GL_R32F, size, size);
    map_.setFilter(GL_NEAREST, GL_NEAREST);
    map_.setWrap(GL_CLAMP_TO_BORDER, glm::vec4(0.0f));
  }

  // Rasterizes the shape at texel centres (what the shadow-map pass does).
  void upload(const Shape& occluded) {
    std::vector<float> depth(std::size_t(size_) * size_);
    for (int y = 0; y < size_; ++y)
      for (int x = 0; x < size_; ++x) depth[y * size_ + x] = occluded(x + 0.5, y + 0.5) ? kOccluder : kReceiver;
    glTextureSubImage2D(map_.id(), 0, 0, 0, size_, size_, GL_RED, GL_FLOAT, depth.data());
  }

  // Visibility at light-space points given in texel units.
  std::vector<float> run(Function function, const std::vector<glm::vec2>& points, const Options& o = {}) {
    std::vector<glm::vec4> samples;
    for (const auto& p : points) samples.emplace_back(p / float(size_), kReceiver, 0.0f);
    Buffer in = Buffer::create(samples.size() * sizeof(glm::vec4), samples.data());
    Buffer out = Buffer::create(samples.size() * sizeof(float), nullptr);
    if (function == kRpcfSmsrScreen || function == kRpcfRsmssScreen) {
      // The tile bounds the screen pass classifies from, for this kernel (rpcf_tiles.h).
      PassTimer timer;
      tiles_->render(map_, o.kernel, timer);
      timer.resolve();
      tiles_->bind(program_);
    }
    {
      PassTimer timer;
      depthImage_->update(map_, timer);  // what rvStoredDepth reads
      timer.resolve();
    }
    program_.use();
    glBindTextureUnit(kShadowMapTextureUnit, map_.id());
    program_.set("uShadowMap", kShadowMapTextureUnit);
    program_.set("uShadowMapSize", glm::ivec2(size_));
    program_.set("uMaxSearch", o.maxSearch);
    program_.set("uEpsilon", 2.5e-5f);
    program_.set("uBias", 0.0f);
    program_.set("uImproved", o.improved ? 1 : 0);
    program_.set("uKernel", o.kernel);
    program_.set("uRow", o.row);
    program_.set("uFunction", int(function));
    program_.set("uCount", int(samples.size()));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProbeInputBufferBinding, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProbeOutputBufferBinding, out.id());
    glDispatchCompute(GLuint((samples.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> result(samples.size());
    glGetNamedBufferSubData(out.id(), 0, GLsizeiptr(result.size() * sizeof(float)), result.data());
    checkGlError("probe");
    return result;
  }

 private:
  int size_;
  Program program_;
  Texture map_;
  std::optional<revectorization::RpcfTiles> tiles_;  // made once the context is current
  std::optional<DepthImage> depthImage_;
};

Probe& probe() {
  static Probe instance;
  return instance;
}

// kPerTexel² samples per texel over texels [x0, x1) × [y0, y1), nudged off the exact
// fractions where eq. 7's strict "< 0.5" would tie (a tie is lit on one side, shadow on
// the other, which is not an asymmetry of the function).
std::vector<glm::vec2> grid(int x0, int y0, int x1, int y1) {
  std::vector<glm::vec2> points;
  for (int y = y0 * kPerTexel; y < y1 * kPerTexel; ++y)
    for (int x = x0 * kPerTexel; x < x1 * kPerTexel; ++x)
      points.emplace_back((x + 0.5137f) / kPerTexel, (y + 0.4871f) / kPerTexel);
  return points;
}

struct Errors {
  int falseLit = 0, falseShadow = 0;
  int total() const { return falseLit + falseShadow; }
};

Errors classify(const std::vector<float>& v, const std::vector<glm::vec2>& points, const Shape& occluded) {
  Errors e;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const bool shadow = occluded(points[i].x, points[i].y);
    const bool lit = v[i] >= 0.5f;
    e.falseLit += shadow && lit;
    e.falseShadow += !shadow && !lit;
  }
  return e;
}

// Half-planes "above" a line y = y0 + slope·(x − 16) (shallow) or right of
// x = x0 + slope·(y − 16) (steep), each in both orientations.
struct Edge {
  std::string name;
  Shape occluded;
};

std::vector<Edge> staircases() {
  std::vector<Edge> edges;
  for (const double slope : {1.0 / 5.0, 2.0 / 7.0, 1.0 / 3.0, 0.6, 1.0})
    for (const int orientation : {0, 1, 2, 3}) {
      const double offset = 16.37;  // sub-texel phase away from texel centres
      Shape s;
      switch (orientation) {
        case 0: s = [=](double x, double y) { return y > offset + slope * (x - 16); }; break;
        case 1: s = [=](double x, double y) { return y < offset - slope * (x - 16); }; break;
        case 2: s = [=](double x, double y) { return x > offset + slope * (y - 16); }; break;
        default: s = [=](double x, double y) { return x < offset - slope * (y - 16); }; break;
      }
      char name[64];
      std::snprintf(name, sizeof name, "slope %.3f orientation %d", slope, orientation);
      edges.push_back({name, s});
    }
  return edges;
}

// How many of `values` lie strictly between 0 and 1 (filtered), and how many outside [0, 1]
// (NaN included).
int strictlyBetween(const std::vector<float>& values) {
  return int(std::count_if(values.begin(), values.end(), [](float v) { return v > 0.0f && v < 1.0f; }));
}
// Two code paths that compute one function (RPCF's 1×1 kernel and its base): bit for bit on
// llvmpipe, measured; the GL specification does not promise it of different code
// (test::expectSameVisibilityAcrossPrograms says what it does promise), so elsewhere at most
// 1 % of the points may differ, by a rounding tie in a depth test, and only by more than 0.01.
void expectSameValuesOnBothPaths(const std::vector<float>& a, const std::vector<float>& b) {
  ASSERT_EQ(a.size(), b.size());
  if (test::onLlvmpipe()) {
    EXPECT_EQ(a, b);
    return;
  }
  std::size_t off = 0;
  for (std::size_t i = 0; i < a.size(); ++i) off += !(std::abs(a[i] - b[i]) <= 0.01f);
  EXPECT_LE(off, a.size() / 100);
}

int outsideTheUnitInterval(const std::vector<float>& values) {
  return int(std::count_if(values.begin(), values.end(), [](float v) { return !(v >= 0.0f && v <= 1.0f); }));
}

// Runs `check` once per staircase, its occluder uploaded to the probe and its name traced.
template <typename Check>
void forEachStaircase(Probe& p, Check check) {
  for (const auto& edge : staircases()) {
    SCOPED_TRACE(edge.name);
    p.upload(edge.occluded);
    check(edge);
  }
}

// Improved SMSR (EDTSM* eq. 7) and RSMSS put the edge closer to the true line than the
// stair: fewer wrongly classified samples than the shadow test. Conservative SMSR (eq. 4)
// only ever adds shadow on the lit side (entering discontinuities), so its false-lit
// samples are at most sm's; its line is parallel to the true one but half a texel into
// the lit side (the overestimation EDTSM* §3.1 describes), so it misclassifies about
// twice as many samples as the stair.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
TEST(RevectorizationGlsl, RevectorizedEdgeIsCloserToTheLineThanTheStair) {
  Probe& p = probe();
  const auto points = grid(6, 6, 26, 26);
  std::cout << "edge                        samples wrong: sm  smsr-cons  smsr-impr  rsmss\n";
  int smSum = 0, consSum = 0, imprSum = 0, rsmssSum = 0;
  forEachStaircase(p, [&](const Edge& edge) {
    const Errors sm = classify(p.run(kShadowTest, points), points, edge.occluded);
    const Errors cons = classify(p.run(kSmsr, points), points, edge.occluded);
    const Errors impr = classify(p.run(kSmsr, points, {.improved = true}), points, edge.occluded);
    const Errors rsmss = classify(p.run(kRsmss, points), points, edge.occluded);
    std::printf("%-28s %20d %10d %10d %6d\n", edge.name.c_str(), sm.total(), cons.total(), impr.total(),
                rsmss.total());
    EXPECT_LT(impr.total(), sm.total());
    EXPECT_LT(rsmss.total(), sm.total());
    EXPECT_LE(cons.falseLit, sm.falseLit);
    EXPECT_GE(cons.falseShadow, sm.falseShadow);
    EXPECT_LT(impr.falseShadow, cons.falseShadow);  // EDTSM*: improved overestimates less
    smSum += sm.total(), consSum += cons.total(), imprSum += impr.total(), rsmssSum += rsmss.total();
  });
  std::printf("%-28s %20d %10d %10d %6d\n", "sum", smSum, consSum, imprSum, rsmssSum);
  std::fflush(stdout);
  EXPECT_LT(imprSum * 2, smSum);  // the improved line is close to exact on ideal staircases
  // Per run of L texels, the stair misclassifies two triangles of area L/8 (texel²); eq. 4's
  // line, half a texel into the lit side, misclassifies L/2: twice the stair's error.
  const double ratio = double(consSum) / smSum;
  std::printf("conservative / sm wrong samples: %.2f (geometry: 2)\n", ratio);
  EXPECT_NEAR(ratio, 2.0, 0.35);
}

// Conservative SMSR's line on an ideal staircase is the true line moved half a texel
// (across the run's axis) into the lit side: on a shallow edge, every lit sample more than
// half a texel below the line stays lit, and every sample above the shifted line is shadow.
TEST(RevectorizationGlsl, ConservativeLineIsTheTrueLineHalfATexelIntoTheLitSide) {
  Probe& p = probe();
  const double slope = 0.2, offset = 16.37;
  const Shape occluded = [=](double x, double y) { return y > offset + slope * (x - 16); };
  p.upload(occluded);
  const auto points = grid(8, 8, 24, 24);
  const auto v = p.run(kSmsr, points);
  int wrong = 0, near = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const double below = offset + slope * (points[i].x - 16) - points[i].y;  // > 0: lit side
    const double margin = below - 0.5;
    if (std::abs(margin) < 0.08) {  // the stair's quantization around the shifted line
      ++near;
      continue;
    }
    wrong += (margin > 0) != (v[i] >= 0.5f);
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(near, 0);
}

// I: a straight axis-aligned edge crossing the whole map is left as the shadow test says.
TEST(RevectorizationGlsl, StraightRunsKeepTheShadowTest) {
  Probe& p = probe();
  for (const int axis : {0, 1}) {
    const Shape occluded = [=](double x, double y) { return (axis == 0 ? y : x) > 16.0; };
    p.upload(occluded);
    const auto points = grid(0, 0, kSize, kSize);
    const auto sm = p.run(kShadowTest, points);
    expectSameValuesOnBothPaths(p.run(kSmsr, points), sm);
    expectSameValuesOnBothPaths(p.run(kSmsr, points, {.improved = true}), sm);
    expectSameValuesOnBothPaths(p.run(kRsmss, points), sm);
  }
}

// L: one step of a staircase (shadow above row 16 right of column 16, above row 17
// elsewhere): the lit run under the step's upper tread is clipped near the corner only.
TEST(RevectorizationGlsl, LShapedStepIsClippedTowardsItsCorner) {
  Probe& p = probe();
  const Shape occluded = [](double x, double y) { return y > (x > 16.0 ? 16.0 : 17.0); };
  p.upload(occluded);
  // Row 16, columns 0..15: lit texels with shadow above; the run ends at column 16
  // (shadow) and begins at the map's border, so L = 16.
  auto at = [&](Function f, float x, float y, Options o = {}) { return p.run(f, {{x, y}}, o)[0]; };
  EXPECT_EQ(at(kSmsr, 15.9f, 16.9f), 0.0f);  // at the corner: shadow
  EXPECT_EQ(at(kSmsr, 15.9f, 16.1f), 0.0f);  // conservative: the whole corner texel
  EXPECT_EQ(at(kSmsr, 1.5f, 16.5f), 1.0f);   // far from the corner: lit
  EXPECT_EQ(at(kSmsr, 15.9f, 16.9f, {.improved = true}), 0.0f);
  EXPECT_EQ(at(kSmsr, 15.9f, 16.1f, {.improved = true}), 1.0f);  // improved: half height
  EXPECT_EQ(at(kSmsr, 12.5f, 16.9f, {.improved = true}), 0.0f);  // improved: within half the run
  EXPECT_EQ(at(kSmsr, 4.5f, 16.9f, {.improved = true}), 1.0f);   // beyond it
  // The shadowed side of the same step (row 16, column 16..) is opened by improved only.
  EXPECT_EQ(at(kSmsr, 16.1f, 16.1f), 0.0f);
  EXPECT_EQ(at(kSmsr, 16.1f, 16.1f, {.improved = true}), 1.0f);
  const float r = at(kRsmss, 15.5f, 16.5f);
  EXPECT_GT(r, 0.0f);
  EXPECT_LT(r, 1.0f);
}

// U: a lit notch of 3 texels in row 16 under shadow, shadowed at both ends. Conservative
// SMSR fills it; improved and RSMSS close it from both ends (tent), keeping its middle lit
// near the bottom. Opposite neighbours (a 1-texel notch) are a U of length 1.
TEST(RevectorizationGlsl, UShapedNotchesAreClosed) {
  Probe& p = probe();
  for (const int width : {1, 3}) {
    SCOPED_TRACE("notch width " + std::to_string(width));
    const Shape occluded = [=](double x, double y) {
      const bool notch = y > 16.0 && y < 17.0 && x > 10.0 && x < 10.0 + width;
      return y > 16.0 && !notch;
    };
    p.upload(occluded);
    const float mid = 10.0f + width * 0.5f;
    auto at = [&](Function f, float x, float y, Options o = {}) { return p.run(f, {{x, y}}, o)[0]; };
    EXPECT_EQ(at(kShadowTest, mid, 16.5f), 1.0f);
    EXPECT_EQ(at(kSmsr, mid, 16.1f), 0.0f);
    EXPECT_EQ(at(kSmsr, mid, 16.9f), 0.0f);
    EXPECT_EQ(at(kSmsr, 10.02f, 16.98f, {.improved = true}), 0.0f);  // next to an end, at the top
    EXPECT_EQ(at(kSmsr, mid, 16.1f, {.improved = true}), 1.0f);      // middle, bottom
    EXPECT_LT(at(kRsmss, 10.02f, 16.98f), 0.5f);
  }
}

// An occluder edge that leaves the map: the map's border (which reads as shadow) is not
// treated as an edge, so texels along it are not clipped against it; a map without any
// occluder stays lit everywhere inside; the part of the edge inside is still improved.
TEST(RevectorizationGlsl, EdgesThatLeaveTheMap) {
  Probe& p = probe();
  p.upload([](double, double) { return false; });
  const auto all = grid(0, 0, kSize, kSize);
  for (const Function f : {kSmsr, kRsmss})
    for (const float v : p.run(f, all, {.improved = true})) EXPECT_EQ(v, 1.0f);
  for (const float v : p.run(kSmsr, all)) EXPECT_EQ(v, 1.0f);

  // Shallow edge entering at the left border.
  const Shape occluded = [](double x, double y) { return y > 3.3 + 0.2 * x; };
  p.upload(occluded);
  const auto border = grid(0, 0, 6, 12);
  const Errors sm = classify(p.run(kShadowTest, border), border, occluded);
  const Errors impr = classify(p.run(kSmsr, border, {.improved = true}), border, occluded);
  const Errors cons = classify(p.run(kSmsr, border), border, occluded);
  std::printf("edge leaving the map, wrong samples: sm %d, smsr-improved %d, smsr-conservative %d\n", sm.total(),
              impr.total(), cons.total());
  EXPECT_LE(impr.total(), sm.total());
  EXPECT_LE(cons.falseLit, sm.falseLit);
  // The column next to the border, far below the edge, is lit as sm says.
  for (const auto& [f, o] : {std::pair{kSmsr, Options{}}, std::pair{kSmsr, Options{.improved = true}}})
    EXPECT_EQ(p.run(f, {{0.1f, 0.5f}}, o)[0], 1.0f);
}

// max_search: on an edge whose runs (40 texels) are longer than 2·max_search, texels
// farther than max_search from both run ends find no end (a straight run) and keep the
// shadow test; with max_search = 64 the same texels are revectorized.
TEST(RevectorizationGlsl, MaxSearchCutsOffLongEdges) {
  Probe& p = probe();
  // Line of slope −1/40 through (20, 16.5): row 17 is all shadow, row 16 is lit left of
  // column 20 and shadow from it on.
  const Shape occluded = [](double x, double y) { return y > 16.5 + (20.0 - x) / 40.0; };
  p.upload(occluded);
  // Row 16's lit texels have shadow above: columns 0..19 (the run leaves the map on the
  // left), its end (shadow in row 16) is column 20; columns 1, 2 are over 16 texels away.
  std::vector<glm::vec2> far{{1.5f, 16.95f}, {2.5f, 16.95f}};
  std::vector<glm::vec2> nearEnd{{19.5f, 16.95f}};
  for (const bool improved : {false, true}) {
    SCOPED_TRACE(improved ? "improved" : "conservative");
    const auto sm = p.run(kShadowTest, far);
    expectSameValuesOnBothPaths(p.run(kSmsr, far, {.improved = improved, .maxSearch = 16}), sm);
    EXPECT_EQ(p.run(kSmsr, nearEnd, {.improved = improved, .maxSearch = 16})[0], 0.0f);
  }
  // With a long enough search the far texels see the end and the conservative line
  // (from the run's beginning at the top edge) clips them near the top.
  const auto longSearch = p.run(kSmsr, far, {.maxSearch = 64});
  EXPECT_EQ(p.run(kShadowTest, far)[0], 1.0f);
  EXPECT_EQ(longSearch[1], 0.0f);
}

// The improved function is symmetric: swapping occluder and lit texels flips the result.
TEST(RevectorizationGlsl, ImprovedVisibilityIsSymmetricInLitAndShadow) {
  Probe& p = probe();
  const auto points = grid(4, 4, 28, 28);
  forEachStaircase(p, [&](const Edge& edge) {
    const auto a = p.run(kSmsr, points, {.improved = true});
    const auto ra = p.run(kRsmss, points);
    p.upload([&](double x, double y) { return !edge.occluded(x, y); });
    const auto b = p.run(kSmsr, points, {.improved = true});
    const auto rb = p.run(kRsmss, points);
    int asymmetric = 0, rsmssAsymmetric = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      asymmetric += a[i] != 1.0f - b[i];
      rsmssAsymmetric += std::abs(ra[i] - (1.0f - rb[i])) > 1e-5f;
    }
    EXPECT_EQ(asymmetric, 0);
    EXPECT_EQ(rsmssAsymmetric, 0);
  });
}

// RSMSS is a visibility in [0, 1], with values strictly between on edges (it filters).
TEST(RevectorizationGlsl, RsmssValuesAreInTheUnitInterval) {
  Probe& p = probe();
  const auto points = grid(0, 0, kSize, kSize);
  forEachStaircase(p, [&](const Edge&) {
    const auto one = p.run(kRsmss, points, {.kernel = 1}), three = p.run(kRpcfRsmss, points, {.kernel = 3});
    EXPECT_EQ(outsideTheUnitInterval(one) + outsideTheUnitInterval(three), 0);
    EXPECT_GT(strictlyBetween(one) + strictlyBetween(three), 0);
  });
}

// rvClassify's two gathers give the shadow test, discontinuity and edge flag that one
// texelFetch per texel gives, inside the map, on its border texels and outside it, for
// both sides.
TEST(RevectorizationGlsl, GatheredClassificationEqualsFetched) {
  Probe& p = probe();
  std::vector<glm::vec2> points = grid(0, 0, kSize, kSize);
  for (const float outside : {-0.6f, -0.1f, kSize + 0.1f, kSize + 0.6f})
    for (int i = 0; i < kSize * 4; ++i) {
      points.emplace_back(outside, i * 0.25f + 0.1f);
      points.emplace_back(i * 0.25f + 0.1f, outside);
    }
  forEachStaircase(p, [&](const Edge&) {
    for (const bool bothSides : {false, true}) {
      const auto gathered = p.run(kClassify, points, {.improved = bothSides});
      expectSameValuesOnBothPaths(gathered, p.run(kClassifyFetched, points, {.improved = bothSides}));
      EXPECT_GT(std::count_if(gathered.begin(), gathered.end(), [](float v) { return v >= 32.0f; }), 0);
    }
  });
}

// RPCF's row masks from gathers (rpcfBlockTests) are the per-texel fetches' (rpcfRowTests)
// on every row of the block and its rim, for blocks inside the map.
TEST(RevectorizationGlsl, GatheredRpcfRowsEqualFetched) {
  Probe& p = probe();
  forEachStaircase(p, [&](const Edge&) {
    for (const int k : {1, 3, 7}) {
      SCOPED_TRACE("kernel " + std::to_string(k));
      const int margin = k / 2 + 1;
      std::vector<glm::vec2> points;  // one receiver per texel whose block lies inside
      for (int y = margin; y < kSize - margin; ++y)
        for (int x = margin; x < kSize - margin; ++x) points.emplace_back(x + 0.37f, y + 0.61f);
      int partial = 0;
      for (int row = 0; row < k + 2; ++row) {
        const Options o{.kernel = k, .row = row};
        const auto gathered = p.run(kBlockRow, points, o);
        SCOPED_TRACE("row " + std::to_string(row));
        expectSameValuesOnBothPaths(gathered, p.run(kFetchedRow, points, o));
        const float all = float((1 << (k + 2)) - 1);
        partial += int(std::count_if(gathered.begin(), gathered.end(), [&](float v) { return v > 0.0f && v < all; }));
      }
      EXPECT_GT(partial, 0);  // rows that straddle the edge
    }
  });
}

// RPCF's block check from the k diagonal taps equals the k² taps' one, also where rounding
// of a tap's uv moves it to the next texel: receivers a few ulps either side of texel
// boundaries, on a map whose texel size 1/48 is no power of two, and near the map's border.
TEST(RevectorizationGlsl, RpcfRegularBlockFromTheDiagonalEqualsAllTaps) {
  constexpr int kOddSize = 48;
  static Probe p(kOddSize);
  std::vector<glm::vec2> points;
  for (int y = 0; y < kOddSize; y += 5)
    for (int x = 0; x < kOddSize; ++x)
      for (const float nudge : {-3e-6f, -4e-7f, 0.0f, 4e-7f, 3e-6f}) {
        points.emplace_back((x + nudge) * (1.0f / kOddSize) * kOddSize, y + 0.5f);
        points.emplace_back(x + nudge, y + nudge);
        points.emplace_back(y + 0.37f, x + nudge);
      }
  for (const int k : {1, 3, 5, 7}) {
    SCOPED_TRACE("kernel " + std::to_string(k));
    const auto diagonal = p.run(kRegularBlock, points, {.kernel = k});
    expectSameValuesOnBothPaths(diagonal, p.run(kRegularBlockPlain, points, {.kernel = k}));
    EXPECT_GT(std::count(diagonal.begin(), diagonal.end(), 1.0f), 0);
    EXPECT_GT(std::count(diagonal.begin(), diagonal.end(), 0.0f), 0);
  }
}

// The screen pass's RPCF (classified from the tile bounds, else the edge taps only, each
// classified from the masks, or by rvClassify where the block leaves the map) gives the
// plain k×k loop's very number, on the whole map and beyond its border.
TEST(RevectorizationGlsl, RpcfScreenPassEqualsThePlainLoop) {
  Probe& p = probe();
  std::vector<glm::vec2> points;
  for (int y = -2; y < kSize + 2; ++y)
    for (int x = -2; x < kSize + 2; ++x) points.emplace_back(x + 0.37f, y + 0.61f);
  forEachStaircase(p, [&](const Edge&) {
    for (const int k : {3, 5}) {
      SCOPED_TRACE("kernel " + std::to_string(k));
      for (const bool improved : {false, true})
        expectSameValuesOnBothPaths(p.run(kRpcfSmsrScreen, points, {.improved = improved, .kernel = k}),
                                    p.run(kRpcfSmsr, points, {.improved = improved, .kernel = k}));
      expectSameValuesOnBothPaths(p.run(kRpcfRsmssScreen, points, {.kernel = k}),
                                  p.run(kRpcfRsmss, points, {.kernel = k}));
    }
  });
}

// Where the walks read stored depths is a matter of speed only (depth_image.h): the
// depth texture itself (the paper path), the 2×2-block image and the per-texel image
// (the fast path's) give every function
// the very same numbers, on a map of odd size (the blocks' last row and column are
// half-filled) and beyond its border.
TEST(RevectorizationGlsl, EveryDepthLayoutGivesTheSameNumbers) {
  using Layout = DepthImage::Layout;
  constexpr int kOddSize = 33;
  static Probe texture(kOddSize, Layout::Texture), blocks(kOddSize, Layout::Blocks), texels(kOddSize, Layout::Texels);
  std::vector<glm::vec2> points;
  for (int y = -2 * kPerTexel; y < (kOddSize + 2) * kPerTexel; y += 3)
    for (int x = -2 * kPerTexel; x < (kOddSize + 2) * kPerTexel; x += 3)
      points.emplace_back((x + 0.5137f) / kPerTexel, (y + 0.4871f) / kPerTexel);
  std::vector<Edge> shapes = staircases();
  shapes.push_back({"checker of 3×2 texels", [](double x, double y) { return (int(x / 3) + int(y / 2)) % 2 == 0; }});
  for (const auto& shape : shapes) {
    SCOPED_TRACE(shape.name);
    for (Probe* p : {&texture, &blocks, &texels}) p->upload(shape.occluded);
    for (const auto& [function, o] : std::vector<std::pair<Function, Options>>{
             {kSmsr, {}}, {kSmsr, {.improved = true}}, {kRsmss, {}},
             {kRpcfSmsr, {.kernel = 3}}, {kRpcfSmsrScreen, {.improved = true, .kernel = 3}},
             {kRpcfRsmssScreen, {.kernel = 5}}}) {
      SCOPED_TRACE("function " + std::to_string(int(function)));
      const auto reference = texture.run(function, points, o);
      EXPECT_GT(strictlyBetween(reference) + int(std::count(reference.begin(), reference.end(), 0.0f)), 0);
      expectSameValuesOnBothPaths(blocks.run(function, points, o), reference);
      expectSameValuesOnBothPaths(texels.run(function, points, o), reference);
    }
  }
}

// RPCF with a 1×1 kernel is its base function (eqs. 2 and 3): bit for bit on llvmpipe.
TEST(RevectorizationGlsl, RpcfWithKernelOneEqualsItsBase) {
  Probe& p = probe();
  const auto points = grid(0, 0, kSize, kSize);
  forEachStaircase(p, [&](const Edge&) {
    for (const bool improved : {false, true})
      expectSameValuesOnBothPaths(p.run(kRpcfSmsr, points, {.improved = improved, .kernel = 1}),
                                  p.run(kSmsr, points, {.improved = improved}));
    expectSameValuesOnBothPaths(p.run(kRpcfRsmss, points, {.kernel = 1}), p.run(kRsmss, points));
    // A wider kernel filters: values strictly between 0 and 1 appear.
    EXPECT_GT(strictlyBetween(p.run(kRpcfSmsr, points, {.kernel = 3})), 0);
  });
}

// The widest kernels (31², the EDTSM* paper's largest, and 29²) on a map wide enough for
// the block and its rim: the screen pass's row masks classify and walk the edge taps of a
// whole row in one word, and give the plain k×k loop's very number; that loop is the mean
// of the base function at the k² taps, summed row by row here on the CPU.
TEST(RevectorizationGlsl, WidestRpcfKernelsAreTheMeanOfTheirTaps) {
  constexpr int kWide = 64;
  static Probe p(kWide);
  std::vector<glm::vec2> points;  // receivers whose 31×31 block and rim lie inside the map
  for (int y = 16; y < 48; y += 3)
    for (int x = 16; x < 48; x += 3) points.emplace_back(x + 0.5137f, y + 0.4871f);
  const std::vector<Edge> edges = staircases();
  for (std::size_t e = 0; e < edges.size(); e += 3) {  // every orientation, most slopes
    const Edge& edge = edges[e];
    SCOPED_TRACE(edge.name);
    p.upload(edge.occluded);
    for (const int k : {29, 31}) {
      SCOPED_TRACE("kernel " + std::to_string(k));
      const int h = k / 2;
      std::vector<glm::vec2> taps;
      for (const auto& q : points)
        for (int dy = -h; dy <= h; ++dy)
          for (int dx = -h; dx <= h; ++dx) taps.push_back(q + glm::vec2(dx, dy));
      struct Variant {
        Function base, plain, screen;
        bool improved;
      };
      for (const Variant& v : {Variant{kSmsr, kRpcfSmsr, kRpcfSmsrScreen, false},
                               Variant{kSmsr, kRpcfSmsr, kRpcfSmsrScreen, true},
                               Variant{kRsmss, kRpcfRsmss, kRpcfRsmssScreen, false}}) {
        const Options o{.improved = v.improved, .kernel = k};
        const std::vector<float> atTaps = p.run(v.base, taps, o);
        const std::vector<float> plain = p.run(v.plain, points, o);
        expectSameValuesOnBothPaths(p.run(v.screen, points, o), plain);
        int partial = 0;
        for (std::size_t i = 0; i < points.size(); ++i) {
          float sum = 0.0f;
          for (int t = 0; t < k * k; ++t) sum += atTaps[i * std::size_t(k * k) + std::size_t(t)];
          EXPECT_NEAR(plain[i], sum / float(k * k), 1e-6f) << "receiver " << i;
          partial += plain[i] > 0.0f && plain[i] < 1.0f;
        }
        EXPECT_GT(partial, 0);  // the blocks do straddle the edge
      }
    }
  }
}

}  // namespace
}  // namespace testbed
