// silhouette_map.glsl through a compute probe (the notes' point-picking cases and the
// skewed quadrants, reflex ones included) and the CPU silhouette extraction on shapes
// whose silhouettes are known.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "techniques/silhouette_map/silhouette_edges.h"
#include "testbed/gl/depth_format.h"
#include "testbed/gl/objects.h"
#include "testbed/glsl/units.h"
#include "testbed/render/shadow_map_pass.h"
#include "testbed/scene/primitives.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

// Runs the probe on cases of 3 vec4 each; one vec4 result per case.
std::vector<glm::vec4> probe(int mode, const std::vector<glm::vec4>& cases) {
  test::sharedContext();
  const Program program = Program::compute("techniques/silhouette_map/silhouette_map_probe.comp");
  const std::size_t n = cases.size() / 3;
  Buffer in = Buffer::create(cases.size() * sizeof(glm::vec4), cases.data());
  Buffer out = Buffer::create(n * sizeof(glm::vec4), nullptr);
  program.use();
  program.set("uMode", mode);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProbeInputBufferBinding, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProbeOutputBufferBinding, out.id());
  glDispatchCompute(static_cast<GLuint>(n), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> results(n);
  glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(n * sizeof(glm::vec4)), results.data());
  return results;
}

void expectNear(const glm::vec4& actual, const glm::vec4& expected) {
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(actual[i], expected[i], 1e-5f) << "component " << i;
}

TEST(SilhouetteMapGlsl, PointPickingFollowsTheNotesCases) {
  // (a.xyz, b.xyz) in the texel's local coordinates; z is light depth.
  const std::vector<std::pair<glm::vec3, glm::vec3>> edges = {
      {{0.3f, 0.4f, 0.2f}, {3.0f, 3.0f, 0.5f}},     // endpoint a inside: a
      {{-2.0f, 0.5f, 0.0f}, {0.7f, 0.6f, 1.0f}},    // endpoint b inside: b
      {{-0.5f, 0.9f, 0.0f}, {0.9f, -0.5f, 1.4f}},   // cuts corner (0,0): crosses y = x only
      {{-1.0f, 0.25f, 0.0f}, {2.0f, 0.25f, 3.0f}},  // crosses both diagonals: their midpoint
      {{1.2f, -1.0f, 0.0f}, {2.0f, 0.5f, 0.0f}},    // misses the texel (conservative extra)
      {{-0.6f, 0.5f, 0.0f}, {0.5f, -0.6f, 0.0f}},   // passes outside corner (0,0): x + y = −0.1
  };
  std::vector<glm::vec4> cases;
  for (const auto& [a, b] : edges) {
    cases.emplace_back(a, 0.0f);
    cases.emplace_back(b, 0.0f);
    cases.emplace_back(0.0f);
  }
  const auto r = probe(0, cases);
  expectNear(r[0], {0.3f, 0.4f, 0.2f, 1});
  expectNear(r[1], {0.7f, 0.6f, 1.0f, 1});
  expectNear(r[2], {0.2f, 0.2f, 0.7f, 1});   // t = 0.5 along the edge
  expectNear(r[3], {0.5f, 0.25f, 1.5f, 1});  // crossings at x = 0.25 and 0.75
  EXPECT_EQ(r[4].w, 0.0f);
  EXPECT_EQ(r[5].w, 0.0f);
}

// A texel's silhouette point and its four neighbours' (right, up, left, down), texel units.
struct FivePoints {
  glm::vec2 c, right, up, left, down;
};

struct QuadrantCase {
  FivePoints points;
  glm::vec2 f;
  int corner;
};

TEST(SilhouetteMapGlsl, QuadrantsAreSkewedByTheFivePoints) {
  const glm::vec2 right{1.5f, 0.5f}, left{-0.5f, 0.5f}, down{0.5f, -0.5f};
  // No silhouette around: every point at its texel's centre.
  const FivePoints centres{{0.5f, 0.5f}, right, {0.5f, 1.5f}, left, down};
  // A near-vertical silhouette x = 0.3 + 0.1 y through this texel and its upper and
  // lower neighbours: the side of the line decides, not the nearest corner.
  const FivePoints onALine{{0.35f, 0.5f}, right, {0.45f, 1.5f}, left, {0.25f, -0.5f}};
  // The texel's point near corner (1,1), its right and up neighbours' points near their
  // far sides: quadrant 3 is a reflex sweep (> 180°) and (0.9, 0.9) belongs to corner 0.
  const FivePoints reflex{glm::vec2{0.95f}, {1.5f, 0.05f}, {0.05f, 1.5f}, left, down};
  const std::vector<QuadrantCase> cases = {
      // The four axis-aligned quarters, i.e. sm's nearest sample.
      {centres, {0.8f, 0.9f}, 3}, {centres, {0.2f, 0.9f}, 2}, {centres, {0.2f, 0.1f}, 0}, {centres, {0.9f, 0.2f}, 1},
      {onALine, {0.40f, 0.9f}, 3}, {onALine, {0.38f, 0.9f}, 2}, {onALine, {0.30f, 0.1f}, 0}, {onALine, {0.32f, 0.1f}, 1},
      {reflex, {0.90f, 0.20f}, 1},  {reflex, {0.90f, 0.90f}, 0},  {reflex, {0.97f, 0.99f}, 3},  {reflex, {0.20f, 0.90f}, 2},
  };
  std::vector<glm::vec4> data;
  for (const auto& q : cases) {
    data.emplace_back(q.points.c, q.points.right);
    data.emplace_back(q.points.up, q.points.left);
    data.emplace_back(q.points.down, q.f);
  }
  const auto r = probe(1, data);
  for (std::size_t i = 0; i < cases.size(); ++i) EXPECT_EQ(int(r[i].x), cases[i].corner) << "case " << i;
}

// The corner tests by one textureGather (silhouette_corners.glsl, the visibility and point
// passes' fast path) against four shadowTestTexel lookups, on a random depth map of each
// depth format: every silhouette texel 0..N (the corners outside the map read the border),
// receiver depths drawn around and exactly at the stored ones (the ties of <=), with and
// without a bias.
TEST(SilhouetteMapGlsl, GatheredCornerTestsEqualFourLookups) {
  test::sharedContext();
  constexpr int n = 16;
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> depths(n * n);
  for (float& d : depths) d = unit(random);
  const Program program = Program::compute("techniques/silhouette_map/silhouette_corners_probe.comp");
  for (const DepthFormat format : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) {
    Texture map = Texture::create2D(depthInternalFormat(format), n, n);
    glTextureSubImage2D(map.id(), 0, 0, 0, n, n, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
    map.setFilter(GL_NEAREST, GL_NEAREST);
    map.setWrap(GL_CLAMP_TO_BORDER, glm::vec4(0.0f));  // as the shadow map pass sets it
    const std::vector<float> stored = map.readFloats(1);
    std::vector<glm::vec4> cases;
    for (int y = 0; y <= n; ++y)
      for (int x = 0; x <= n; ++x) {
        const int near = std::clamp(y, 0, n - 1) * n + std::clamp(x, 0, n - 1);
        for (const float depth : {stored[std::size_t(near)], unit(random), 0.0f, 1.0f})
          for (const float bias : {0.0f, 0.01f}) cases.emplace_back(float(x), float(y), depth + bias * (x & 1), bias);
      }
    Buffer in = Buffer::create(cases.size() * sizeof(glm::vec4), cases.data());
    Buffer out = Buffer::create(2 * cases.size() * sizeof(glm::vec4), nullptr);
    program.use();
    bindShadowMap(program, map);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProbeInputBufferBinding, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kProbeOutputBufferBinding, out.id());
    glDispatchCompute(static_cast<GLuint>(cases.size()), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> results(2 * cases.size());
    glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(results.size() * sizeof(glm::vec4)), results.data());
    int lit = 0, differing = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
      differing += results[2 * i] != results[2 * i + 1];
      lit += results[2 * i + 1] != glm::vec4(0.0f) && results[2 * i + 1] != glm::vec4(1.0f);  // mixed corners
    }
    EXPECT_EQ(differing, 0) << depthFormatName(format);
    EXPECT_GT(lit, int(cases.size() / 4)) << "the cases should mostly disagree between corners";
  }
}

LightTransforms sun(glm::vec3 direction) {
  LightTransforms light;
  light.orthographic = true;
  light.direction = glm::normalize(direction);
  return light;
}

TEST(SilhouetteEdges, BoxUnderASunStraightDownHasItsFourTopEdges) {
  // Side faces are edge-on (dot = 0), which counts as facing away, as in the ground truth.
  std::vector<glm::vec4> out;
  EXPECT_EQ(appendSilhouetteEdges(meshTopology(makeBox(2, 2, 2)), sun({0, -1, 0}), out), 4u);
  ASSERT_EQ(out.size(), 8u);
  for (const auto& p : out) EXPECT_FLOAT_EQ(p.y, 1.0f);
}

TEST(SilhouetteEdges, BoxUnderAnObliqueSunHasASixEdgeOutline) {
  // Three faces lit, three away: the silhouette is the hexagon around the box's shadow.
  std::vector<glm::vec4> out;
  EXPECT_EQ(appendSilhouetteEdges(meshTopology(makeBox(2, 2, 2)), sun({-0.3f, -1, -0.5f}), out), 6u);
}

TEST(SilhouetteEdges, OpenPlaneContributesItsBoundaryOnly) {
  std::vector<glm::vec4> out;
  EXPECT_EQ(appendSilhouetteEdges(meshTopology(makePlane(10, 10, 4)), sun({0.2f, -1, 0}), out), 16u);
}

TEST(SilhouetteEdges, SpotLightFacingIsPerFace) {
  // A spot light straight above sees the top face only; the sides face away from it.
  LightTransforms light;
  light.position = {0, 10, 0};
  std::vector<glm::vec4> out;
  EXPECT_EQ(appendSilhouetteEdges(meshTopology(makeBox(2, 2, 2)), light, out), 4u);
}

}  // namespace
}  // namespace testbed
