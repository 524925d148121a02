#include "groundtruth/volume_geometry.h"

namespace testbed {
namespace {

glm::vec3 toGlm(const OpenMesh::Vec3f& p) { return {p[0], p[1], p[2]}; }

glm::vec4 planeThrough(const glm::vec3& normal, const glm::vec3& point) {
  const float length = glm::length(normal);
  if (length == 0.0f) return {0, 0, 0, 1};
  const glm::vec3 n = normal / length;
  return {n, -glm::dot(n, point)};
}

enum Facing : signed char { kNone = 0, kTowards = 1, kAway = -1 };

}  // namespace

bool isClosed(const TriMesh& mesh) {
  for (const auto edge : mesh.edges())
    if (mesh.is_boundary(edge)) return false;
  return true;
}

VolumeStats appendShadowVolume(const TriMesh& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out) {
  VolumeStats stats;
  const bool closed = isClosed(mesh);
  (closed ? stats.closedMeshes : stats.openMeshes) = 1;

  // Facing of each face, from its vertices (not stored normals) so orientation is exact.
  std::vector<Facing> facing(mesh.n_faces(), kNone);
  for (const auto face : mesh.faces()) {
    auto fv = face.vertices().begin();
    const glm::vec3 a = toGlm(mesh.point(*fv++)), b = toGlm(mesh.point(*fv++)), c = toGlm(mesh.point(*fv));
    const glm::vec3 normal = glm::cross(b - a, c - a);
    if (normal == glm::vec3(0)) continue;
    const glm::vec3 towardsLight = light.directional ? -light.direction : light.position - (a + b + c) / 3.0f;
    const float d = glm::dot(normal, towardsLight);
    facing[face.idx()] = d > 0 ? kTowards : kAway;  // edge-on faces block nothing either way
  }

  // A point extruded away from the light to infinity.
  auto atInfinity = [&](const glm::vec3& p) {
    return light.directional ? glm::vec4(light.direction, 0) : glm::vec4(p - light.position, 0);
  };
  auto emit = [&](const glm::vec4& p, const glm::vec4& q, const glm::vec4& r, const glm::vec4& plane) {
    out.push_back({p, plane});
    out.push_back({q, plane});
    out.push_back({r, plane});
  };

  for (const auto face : mesh.faces()) {
    const Facing f = facing[face.idx()];
    if (f == kNone || (closed && f == kAway)) continue;
    // Corners ordered so the triangle is counter-clockwise seen from the light.
    glm::vec3 corner[3];
    OpenMesh::SmartHalfedgeHandle edges[3];
    int i = 0;
    for (const auto he : face.halfedges()) {
      corner[i] = toGlm(mesh.point(he.from()));
      edges[i++] = he;
    }
    if (f == kAway) std::swap(corner[1], corner[2]);
    const glm::vec4 capPlane = planeThrough(glm::cross(corner[1] - corner[0], corner[2] - corner[0]), corner[0]);
    emit(glm::vec4(corner[0], 1), glm::vec4(corner[1], 1), glm::vec4(corner[2], 1), capPlane);
    ++stats.capTriangles;
    if (!light.directional) {  // a directional dark cap collapses to one point at infinity
      emit(atInfinity(corner[0]), atInfinity(corner[2]), atInfinity(corner[1]), glm::vec4(0, 0, 0, 1));
      ++stats.capTriangles;
    }
    // Side quads on the region's boundary: the neighbour is missing or faces otherwise.
    for (const auto he : edges) {
      const auto opposite = he.opp().face();
      if (opposite.is_valid() && facing[opposite.idx()] == f) continue;
      // Edge a → b in the light-facing winding.
      glm::vec3 a = toGlm(mesh.point(he.from())), b = toGlm(mesh.point(he.to()));
      if (f == kAway) std::swap(a, b);
      const glm::vec3 away = light.directional ? light.direction : a - light.position;
      const glm::vec4 plane = planeThrough(glm::cross(a - b, away), a);
      const glm::vec4 a4(a, 1), b4(b, 1), aInf = atInfinity(a), bInf = atInfinity(b);
      emit(b4, a4, aInf, plane);
      emit(b4, aInf, bInf, plane);
      ++stats.sideQuads;
    }
  }
  return stats;
}

}  // namespace testbed
