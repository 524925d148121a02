// Shadow-volume geometry: every volume must be closed and consistently wound (each directed
// edge met once in each direction, points at infinity included), or the counts drift.
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


// Depth-pass geometry: no caps, and the sides of the depth-fail volume with their far ends
// moved from infinity onto the far plane (each far end on the ray from its corner).
TEST(VolumeGeometry, DepthPassSidesEndOnTheFarPlane) {
  const TriMesh box = lifted(makeBox(2, 2, 2), 5);
  for (const VolumeLight& light : {spotAt({3, 20, 1}), directional({0.3f, -1, 0.2f})}) {
    const VolumeMesh mesh = volumeMesh(meshTopology(box));
    const VolumeReach reach = depthPassReach(mesh, light, {-50, -1, -50}, {50, 30, 50});
    ASSERT_TRUE(reach.bounded);
    EXPECT_EQ(reach.farNormal, glm::vec3(0, -1, 0)) << "the floor of the box ends the sides soonest";
    EXPECT_FLOAT_EQ(reach.farOffset, 1.0f);
    std::vector<VolumeVertex> pass, fail;
    const VolumeStats passStats = appendShadowVolume(mesh, light, pass, reach);
    const VolumeStats failStats = appendShadowVolume(mesh, light, fail);
    EXPECT_EQ(passStats.capTriangles, 0u);
    EXPECT_EQ(passStats.sideQuads, failStats.sideQuads);
    std::size_t sides = 0;
    for (std::size_t t = 0; t < fail.size(); t += 3) {
      if (fail[t].lightCap > 0 || fail[t].plane == glm::vec4(0, 0, 0, 1)) continue;  // caps
      for (int i = 0; i < 3; ++i) {
        const glm::vec4 far = fail[t + i].position, bounded = pass[sides + i].position;
        EXPECT_EQ(pass[sides + i].plane, fail[t + i].plane);
        if (far.w != 0) {
          EXPECT_EQ(bounded, far);
          continue;
        }
        EXPECT_EQ(bounded.w, 1.0f);
        EXPECT_NEAR(glm::dot(reach.farNormal, glm::vec3(bounded)), reach.farOffset, 1e-4f);
        // On the ray from the light through the corner: parallel to the point at infinity.
        const glm::vec3 from = light.directional ? glm::vec3(bounded) - glm::vec3(far) : light.position;
        const glm::vec3 along = glm::normalize(glm::vec3(bounded) - from);
        EXPECT_NEAR(glm::length(glm::cross(along, glm::normalize(glm::vec3(far)))), 0.0f, 1e-5f);
      }
      sides += 3;
    }
    EXPECT_EQ(sides, pass.size());
  }
}

TEST(VolumeGeometry, DepthPassFallsBackToInfinityWhenAPointLightIsAmongTheMesh) {
  // A light inside the mesh's box: no plane is crossed outwards by every side.
  const VolumeMesh mesh = volumeMesh(meshTopology(makePlane(10, 10, 2)));
  const VolumeReach reach = depthPassReach(mesh, spotAt({0, 0.5f, 0}), {-50, -50, -50}, {50, 50, 50});
  EXPECT_FALSE(reach.bounded);
  EXPECT_FALSE(reach.lightCaps || reach.darkCaps);
}

TEST(VolumeGeometry, TwinSidesOfOpenMeshesAreDrawnOnceWithWeightTwo) {
  // A folded open strip: two quads meeting at a ridge, the first facing the light, the
  // second away from it, so the ridge is a silhouette between the two regions.
  TriMesh strip;
  const auto a = strip.add_vertex({0, 2, 0}), b = strip.add_vertex({0, 2, 2}), c = strip.add_vertex({2, 3, 0}),
             d = strip.add_vertex({2, 3, 2}), e = strip.add_vertex({4, 1, 0}), f = strip.add_vertex({4, 1, 2});
  strip.add_face(a, b, d);
  strip.add_face(a, d, c);
  strip.add_face(c, d, f);
  strip.add_face(c, f, e);
  strip.request_face_normals();
  strip.update_face_normals();
  const VolumeMesh mesh = volumeMesh(meshTopology(strip));
  const VolumeLight light = directional({2, -1, 0});
  std::vector<VolumeVertex> fail, pass;
  const VolumeStats failStats = appendShadowVolume(mesh, light, fail);
  const VolumeReach reach = depthPassReach(mesh, light, {-50, -50, -50}, {50, 50, 50});
  const VolumeStats passStats = appendShadowVolume(mesh, light, pass, reach);
  EXPECT_EQ(failStats.openMeshes, 1u);
  EXPECT_EQ(failStats.sideQuads, 8u);  // 3 + 3 border edges, the ridge twice
  EXPECT_EQ(passStats.sideQuads, 7u);
  float weight = 0;
  for (const VolumeVertex& v : pass) weight += v.weight;
  EXPECT_EQ(weight, 6.0f * 8);  // the same total weight: one quad (6 corners) counts twice
}

TEST(VolumeGeometry, EyeInVolumeExactlyWhenItsWayToTheLightCrossesATriangle) {
  const VolumeMesh slab = volumeMesh(meshTopology(lifted(makeBox(10, 1, 10), 10)));
  const VolumeLight sun = directional({0, -1, 0}), lamp = spotAt({0, 30, 0});
  for (const VolumeLight& light : {sun, lamp}) {
    EXPECT_TRUE(eyeMayBeInVolume(slab, light, {1, 2, 1}, 100)) << "under the slab";
    EXPECT_FALSE(eyeMayBeInVolume(slab, light, {1, 20, 1}, 100)) << "above it";
    EXPECT_FALSE(eyeMayBeInVolume(slab, light, {30, 2, 1}, 100)) << "beside it";
    EXPECT_TRUE(eyeMayBeInVolume(slab, light, {1, 10, 1}, 100)) << "inside it, below its top";
    // On the shadow's boundary (the way to the light grazes the slab's edge): a tie counts
    // as inside, so that depth-fail decides.
    EXPECT_TRUE(eyeMayBeInVolume(slab, light, {light.directional ? 5.0f : 100.0f / 13.0f, 0, 1}, 100));
  }
}

}  // namespace
}  // namespace testbed
