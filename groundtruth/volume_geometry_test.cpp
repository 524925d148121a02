// Shadow-volume geometry: every volume must be closed and consistently wound (each directed
// edge met once in each direction, points at infinity included), or stencil counts drift.
#include "groundtruth/volume_geometry.h"

#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "testbed/scene/primitives.h"

namespace testbed {
namespace {

using Key = std::tuple<float, float, float, float>;
Key key(const glm::vec4& p) { return {p.x, p.y, p.z, p.w}; }

// Number of directed edges without their reverse partner. Positions are compared exactly:
// the builder computes every shared corner (and its point at infinity) the same way.
int unmatchedEdges(const std::vector<VolumeVertex>& triangles) {
  std::map<std::pair<Key, Key>, int> edges;
  for (std::size_t t = 0; t < triangles.size(); t += 3)
    for (int i = 0; i < 3; ++i) {
      const Key a = key(triangles[t + i].position), b = key(triangles[t + (i + 1) % 3].position);
      auto reverse = edges.find({b, a});
      if (reverse != edges.end() && reverse->second > 0) {
        --reverse->second;
      } else {
        ++edges[{a, b}];
      }
    }
  int unmatched = 0;
  for (const auto& [edge, count] : edges) unmatched += count;
  return unmatched;
}

TriMesh lifted(TriMesh mesh, float y) {
  for (auto v : mesh.vertices()) mesh.point(v)[1] += y;
  mesh.update_normals();
  return mesh;
}

VolumeLight spotAt(glm::vec3 position) { return {false, position, {0, -1, 0}}; }
VolumeLight directional(glm::vec3 direction) { return {true, {0, 0, 0}, glm::normalize(direction)}; }

TEST(VolumeGeometry, BoxUnderSpotLightIsClosedWithFourSilhouetteQuads) {
  const TriMesh box = lifted(makeBox(2, 2, 2), 5);
  std::vector<VolumeVertex> out;
  const VolumeStats stats = appendShadowVolume(box, spotAt({0, 20, 0}), out);
  EXPECT_EQ(stats.closedMeshes, 1u);
  // A point light straight above the centre sees only the top face (2 light caps, 2 dark
  // caps); the four sides face away from it, so the top square's edges are the silhouette.
  EXPECT_EQ(stats.capTriangles, 4u);
  EXPECT_EQ(stats.sideQuads, 4u);
  EXPECT_EQ(out.size(), 3 * (4 + 2 * 4u));
  EXPECT_EQ(unmatchedEdges(out), 0);
}

TEST(VolumeGeometry, ObliqueLightsGiveClosedVolumesForClosedMeshes) {
  for (const TriMesh& mesh : {lifted(makeBox(3, 1, 2), 4), lifted(makeSphere(2, 24, 12), 4),
                              lifted(makeTorus(3, 1, 24, 12), 4), lifted(makeCylinder(1, 3, 16), 4)}) {
    for (const VolumeLight& light : {spotAt({7, 15, -3}), directional({0.3f, -1, 0.2f})}) {
      std::vector<VolumeVertex> out;
      const VolumeStats stats = appendShadowVolume(mesh, light, out);
      EXPECT_EQ(stats.closedMeshes, 1u);
      EXPECT_GT(stats.sideQuads, 0u);
      EXPECT_EQ(unmatchedEdges(out), 0);
    }
  }
}

TEST(VolumeGeometry, OpenMeshesGetVolumesForBothFacings) {
  // A plane whose normal points away from the light still occludes: its away-facing
  // region is closed into a volume too.
  const TriMesh plane = lifted(makePlane(4, 4, 3), 2);
  for (const VolumeLight& light : {spotAt({1, 10, 1}), spotAt({1, -10, 1}), directional({0.2f, 1, 0})}) {
    std::vector<VolumeVertex> out;
    const VolumeStats stats = appendShadowVolume(plane, light, out);
    EXPECT_EQ(stats.openMeshes, 1u);
    EXPECT_EQ(stats.sideQuads, 12u);  // the 3×3 grid's 12 border edges
    EXPECT_EQ(unmatchedEdges(out), 0);
  }
  // A fence is a union of closed boxes with shared, coplanar faces.
  std::vector<VolumeVertex> out;
  appendShadowVolume(makeFence(10, 3, 6, 0.3f, 0.3f, 2), directional({0.4f, -1, 0.7f}), out);
  EXPECT_EQ(unmatchedEdges(out), 0);
}

TEST(VolumeGeometry, DegenerateTrianglesCastNothingAndNeighboursStayClosed) {
  TriMesh mesh;
  const auto a = mesh.add_vertex({0, 1, 0}), b = mesh.add_vertex({1, 1, 0}), c = mesh.add_vertex({0, 1, 1});
  const auto d = mesh.add_vertex({2, 1, 0});  // collinear with a and b
  mesh.add_face(a, c, b);                     // faces +y
  mesh.add_face(a, b, d);                     // zero area, distinct vertices
  mesh.request_face_normals();
  mesh.update_face_normals();
  std::vector<VolumeVertex> out;
  const VolumeStats stats = appendShadowVolume(mesh, spotAt({0.2f, 5, 0.2f}), out);
  EXPECT_EQ(stats.capTriangles, 2u);  // the real triangle's light and dark caps only
  EXPECT_EQ(stats.sideQuads, 3u);
  EXPECT_EQ(unmatchedEdges(out), 0);
}

TEST(VolumeGeometry, CapPlanesPassThroughTheirTrianglesAndFaceTheLight) {
  const TriMesh box = lifted(makeBox(2, 2, 2), 5);
  const glm::vec3 light(3, 20, 1);
  std::vector<VolumeVertex> out;
  appendShadowVolume(box, spotAt(light), out);
  int finite = 0;
  for (std::size_t t = 0; t < out.size(); t += 3) {
    const glm::vec4 plane = out[t].plane;
    for (int i = 0; i < 3; ++i) {
      const glm::vec4 p = out[t + i].position;
      if (p.w == 0) continue;
      EXPECT_NEAR(glm::dot(glm::vec3(plane), glm::vec3(p)) + plane.w, 0.0f, 1e-5f);
      ++finite;
    }
    // Light caps and sides: the light is on the outer side (or, for sides, on the plane).
    if (plane != glm::vec4(0, 0, 0, 1)) EXPECT_GE(glm::dot(glm::vec3(plane), light) + plane.w, -1e-4f);
  }
  EXPECT_GT(finite, 0);
}

}  // namespace
}  // namespace testbed
