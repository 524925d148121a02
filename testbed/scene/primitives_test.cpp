#include "testbed/scene/primitives.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace testbed {
namespace {

constexpr double kPi = std::numbers::pi;

// Divergence theorem: positive only when every triangle faces outwards.
double signedVolume(const TriMesh& mesh) {
  double volume = 0;
  for (const auto f : mesh.faces()) {
    OpenMesh::Vec3d p[3];
    int i = 0;
    for (const auto v : mesh.fv_range(f))
      p[i++] = OpenMesh::vector_cast<OpenMesh::Vec3d>(mesh.point(v));
    volume += OpenMesh::dot(p[0], OpenMesh::cross(p[1], p[2])) / 6.0;
  }
  return volume;
}

double area(const TriMesh& mesh) {
  double total = 0;
  for (const auto f : mesh.faces()) total += mesh.calc_face_area(f);
  return total;
}

int boundaryHalfedges(const TriMesh& mesh) {
  int count = 0;
  for (const auto h : mesh.halfedges()) count += mesh.is_boundary(h) ? 1 : 0;
  return count;
}

int connectedComponents(const TriMesh& mesh) {
  std::vector<bool> seen(mesh.n_vertices(), false);
  int components = 0;
  for (const auto start : mesh.vertices()) {
    if (seen[start.idx()]) continue;
    ++components;
    std::vector<TriMesh::VertexHandle> stack{start};
    seen[start.idx()] = true;
    while (!stack.empty()) {
      const auto v = stack.back();
      stack.pop_back();
      for (const auto w : mesh.vv_range(v)) {
        if (!seen[w.idx()]) {
          seen[w.idx()] = true;
          stack.push_back(w);
        }
      }
    }
  }
  return components;
}

// A triangulated surface of revolution with n segments whose quads are planar trapezoids
// encloses exactly n sin(2 pi / n) times the first moment  ∫∫ r dA  of its (r, y) profile
// polygon. This gives the exact expected volume of the discretised sphere and torus.
double revolvedVolume(const std::vector<std::pair<double, double>>& profile, int segments) {
  double moment = 0;  // Green's theorem: ∫∫ r dA = 1/6 Σ (r_i + r_j)(r_i y_j - r_j y_i)
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const auto [ri, yi] = profile[i];
    const auto [rj, yj] = profile[(i + 1) % profile.size()];
    moment += (ri + rj) * (ri * yj - rj * yi) / 6.0;
  }
  return std::abs(moment) * segments * std::sin(2 * kPi / segments);
}

void expectClosedAndOutward(const TriMesh& mesh) {
  EXPECT_GT(mesh.n_faces(), 0u);
  EXPECT_EQ(boundaryHalfedges(mesh), 0) << "closed primitives must be welded";
  EXPECT_GT(signedVolume(mesh), 0.0) << "triangles must face outwards";
  for (const auto v : mesh.vertices()) EXPECT_NEAR(mesh.normal(v).norm(), 1.0f, 1e-4f);
}

TEST(Primitives, PlaneIsAnUpFacingOpenGrid) {
  const TriMesh plane = makePlane(6.0f, 4.0f, 3);
  EXPECT_EQ(plane.n_vertices(), 16u);
  EXPECT_EQ(plane.n_faces(), 18u);
  EXPECT_NEAR(area(plane), 24.0, 1e-4);
  EXPECT_GT(boundaryHalfedges(plane), 0);
  for (const auto f : plane.faces()) {
    EXPECT_NEAR(plane.normal(f)[1], 1.0f, 1e-6f);
  }
  for (const auto v : plane.vertices()) {
    const auto p = plane.point(v);
    EXPECT_EQ(p[1], 0.0f);
    EXPECT_LE(std::abs(p[0]), 3.0f + 1e-6f);
    EXPECT_LE(std::abs(p[2]), 2.0f + 1e-6f);
    EXPECT_NEAR(plane.normal(v)[1], 1.0f, 1e-6f);
  }
}

TEST(Primitives, BoxIsClosedWithExactVolume) {
  const TriMesh box = makeBox(2.0f, 3.0f, 4.0f);
  EXPECT_EQ(box.n_vertices(), 8u);
  EXPECT_EQ(box.n_faces(), 12u);
  expectClosedAndOutward(box);
  EXPECT_NEAR(signedVolume(box), 24.0, 1e-5);
  EXPECT_NEAR(area(box), 2 * (6.0 + 8.0 + 12.0), 1e-4);
  // Each face normal is an axis pointing away from the centre.
  for (const auto f : box.faces()) {
    const auto n = box.normal(f);
    const auto c = box.calc_face_centroid(f);
    EXPECT_NEAR(std::abs(n[0]) + std::abs(n[1]) + std::abs(n[2]), 1.0f, 1e-6f);
    EXPECT_GT(OpenMesh::dot(n, c), 0.0f);
  }
}

TEST(Primitives, SphereIsClosedWithPolesAndConvergesToTheBall) {
  const int segments = 32, rings = 16;
  const TriMesh sphere = makeSphere(2.0f, segments, rings);
  EXPECT_EQ(sphere.n_vertices(), std::size_t(segments * (rings - 1) + 2));
  EXPECT_EQ(sphere.n_faces(), std::size_t(2 * segments * (rings - 1)));
  expectClosedAndOutward(sphere);
  std::vector<std::pair<double, double>> profile;
  for (int i = 0; i <= rings; ++i)
    profile.push_back({2 * std::sin(kPi * i / rings), 2 * std::cos(kPi * i / rings)});
  profile.front().first = profile.back().first = 0;
  const double volume = signedVolume(sphere);
  EXPECT_NEAR(volume, revolvedVolume(profile, segments), 1e-4 * volume);
  // The inscribed polyhedron loses about (2pi/n)^2/6 + (pi/rings)^2/6 ≈ 1.3% here; allow 2%.
  const double ball = 4.0 / 3.0 * kPi * 8.0;
  EXPECT_LT(volume, ball);
  EXPECT_GT(volume, 0.98 * ball);
  const double fine = signedVolume(makeSphere(2.0f, 128, 64));
  EXPECT_NEAR(fine, ball, 0.002 * ball);
  for (const auto v : sphere.vertices()) EXPECT_NEAR(sphere.point(v).norm(), 2.0f, 1e-5f);
}

TEST(Primitives, MinimalSphereIsStillClosed) {
  const TriMesh sphere = makeSphere(1.0f, 3, 2);
  EXPECT_EQ(sphere.n_faces(), 6u);
  expectClosedAndOutward(sphere);
}

TEST(Primitives, CylinderHasWeldedCapsAndPrismVolume) {
  const int segments = 24;
  const TriMesh cylinder = makeCylinder(1.5f, 4.0f, segments);
  EXPECT_EQ(cylinder.n_vertices(), std::size_t(2 * segments + 2));
  EXPECT_EQ(cylinder.n_faces(), std::size_t(4 * segments));
  expectClosedAndOutward(cylinder);
  // An inscribed n-gon prism: exactly (n/2) r^2 sin(2pi/n) h, within 1.2% of pi r^2 h for n=24.
  const double prism = segments / 2.0 * 1.5 * 1.5 * std::sin(2 * kPi / segments) * 4.0;
  EXPECT_NEAR(signedVolume(cylinder), prism, 1e-4 * prism);
  EXPECT_NEAR(signedVolume(cylinder), kPi * 1.5 * 1.5 * 4.0, 0.012 * kPi * 1.5 * 1.5 * 4.0);
  for (const auto v : cylinder.vertices()) EXPECT_NEAR(std::abs(cylinder.point(v)[1]), 2.0f, 1e-6f);
}

TEST(Primitives, TorusIsClosedWithPappusVolume) {
  const int segments = 48, tube = 16;
  const float major = 3.0f, minor = 1.0f;
  const TriMesh torus = makeTorus(major, minor, segments, tube);
  EXPECT_EQ(torus.n_vertices(), std::size_t(segments * tube));
  EXPECT_EQ(torus.n_faces(), std::size_t(2 * segments * tube));
  expectClosedAndOutward(torus);
  std::vector<std::pair<double, double>> profile;
  for (int j = 0; j < tube; ++j)
    profile.push_back(
        {major + minor * std::cos(2 * kPi * j / tube), minor * std::sin(2 * kPi * j / tube)});
  const double volume = signedVolume(torus);
  EXPECT_NEAR(volume, revolvedVolume(profile, segments), 1e-4 * volume);
  // Pappus: 2 pi^2 R r^2; the 48 x 16 polygons lose about 2.8%, allow 3.5%.
  const double exact = 2 * kPi * kPi * major * minor * minor;
  EXPECT_LT(volume, exact);
  EXPECT_GT(volume, 0.965 * exact);
  // The hole stays empty: no vertex closer to the axis than major - minor.
  for (const auto v : torus.vertices()) {
    const auto p = torus.point(v);
    EXPECT_GE(std::hypot(p[0], p[2]), major - minor - 1e-5f);
  }
}

TEST(Primitives, FenceIsSeparateClosedBoxes) {
  const int bars = 5, rails = 2;
  const TriMesh fence = makeFence(10.0f, 3.0f, bars, 0.2f, 0.3f, rails);
  EXPECT_EQ(fence.n_faces(), std::size_t(12 * (bars + rails)));
  EXPECT_EQ(fence.n_vertices(), std::size_t(8 * (bars + rails)));
  EXPECT_EQ(connectedComponents(fence), bars + rails);
  expectClosedAndOutward(fence);
  const double bar = 0.2 * 3.0 * 0.3, rail = 10.0 * 0.2 * 0.3;
  EXPECT_NEAR(signedVolume(fence), bars * bar + rails * rail, 1e-4);
  float minX = 1e9f, maxX = -1e9f, minY = 1e9f, maxY = -1e9f;
  for (const auto v : fence.vertices()) {
    const auto p = fence.point(v);
    minX = std::min(minX, p[0]);
    maxX = std::max(maxX, p[0]);
    minY = std::min(minY, p[1]);
    maxY = std::max(maxY, p[1]);
    EXPECT_LE(std::abs(p[2]), 0.15f + 1e-6f);
  }
  EXPECT_NEAR(minX, -5.0f, 1e-5f);
  EXPECT_NEAR(maxX, 5.0f, 1e-5f);
  EXPECT_NEAR(minY, 0.0f, 1e-6f);
  EXPECT_NEAR(maxY, 3.0f, 1e-6f);
}

TEST(Primitives, FenceWithOneBarAndNoRails) {
  const TriMesh fence = makeFence(4.0f, 2.0f, 1, 0.5f, 0.5f, 0);
  EXPECT_EQ(connectedComponents(fence), 1);
  expectClosedAndOutward(fence);
  EXPECT_NEAR(signedVolume(fence), 0.5, 1e-5);
}

TEST(Primitives, RejectsNonsenseArguments) {
  EXPECT_THROW(makeBox(0.0f, 1.0f, 1.0f), std::invalid_argument);
  EXPECT_THROW(makeSphere(1.0f, 2, 8), std::invalid_argument);
  EXPECT_THROW(makeTorus(1.0f, 2.0f), std::invalid_argument);
  EXPECT_THROW(makePlane(1.0f, 1.0f, 0), std::invalid_argument);
}

}  // namespace
}  // namespace testbed
