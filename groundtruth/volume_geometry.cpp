#include "groundtruth/volume_geometry.h"

namespace testbed {
namespace {

glm::vec4 planeThrough(const glm::vec3& normal, const glm::vec3& point) {
  const float length = glm::length(normal);
  if (length == 0.0f) return {0, 0, 0, 1};
  const glm::vec3 n = normal / length;
  return {n, -glm::dot(n, point)};
}

enum Facing : signed char { kNone = 0, kTowards = 1, kAway = -1 };

}  // namespace

VolumeStats appendShadowVolume(const TriMesh& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out) {
  return appendShadowVolume(meshTopology(mesh), light, out);
}

VolumeStats appendShadowVolume(const MeshTopology& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out) {
  VolumeStats stats;
  (mesh.closed ? stats.closedMeshes : stats.openMeshes) = 1;
  const std::size_t faces = mesh.corners.size() / 3;

  // Facing of each face, from its corners (not stored normals) so orientation is exact.
  std::vector<Facing> facing(faces, kNone);
  for (std::size_t f = 0; f < faces; ++f) {
    const glm::vec3 &a = mesh.corners[3 * f], &b = mesh.corners[3 * f + 1], &c = mesh.corners[3 * f + 2];
    const glm::vec3 normal = glm::cross(b - a, c - a);
    if (normal == glm::vec3(0)) continue;
    const glm::vec3 towardsLight = light.directional ? -light.direction : light.position - (a + b + c) / 3.0f;
    facing[f] = glm::dot(normal, towardsLight) > 0 ? kTowards : kAway;  // edge-on faces block nothing
  }

  // A point extruded away from the light to infinity.
  auto atInfinity = [&](const glm::vec3& p) {
    return light.directional ? glm::vec4(light.direction, 0) : glm::vec4(p - light.position, 0);
  };
  auto emit = [&](const glm::vec4& p, const glm::vec4& q, const glm::vec4& r, const glm::vec4& plane,
                  float lightCap = 0.0f) {
    out.push_back({p, plane, lightCap});
    out.push_back({q, plane, lightCap});
    out.push_back({r, plane, lightCap});
  };

  for (std::size_t f = 0; f < faces; ++f) {
    const Facing facingHere = facing[f];
    if (facingHere == kNone || (mesh.closed && facingHere == kAway)) continue;
    // Corners ordered so the triangle is counter-clockwise seen from the light.
    glm::vec3 corner[3] = {mesh.corners[3 * f], mesh.corners[3 * f + 1], mesh.corners[3 * f + 2]};
    if (facingHere == kAway) std::swap(corner[1], corner[2]);
    const glm::vec4 capPlane = planeThrough(glm::cross(corner[1] - corner[0], corner[2] - corner[0]), corner[0]);
    emit(glm::vec4(corner[0], 1), glm::vec4(corner[1], 1), glm::vec4(corner[2], 1), capPlane, 1.0f);
    ++stats.capTriangles;
    if (!light.directional) {  // a directional dark cap collapses to one point at infinity
      emit(atInfinity(corner[0]), atInfinity(corner[2]), atInfinity(corner[1]), glm::vec4(0, 0, 0, 1));
      ++stats.capTriangles;
    }
    // Side quads on the region's boundary: the neighbour is missing or faces otherwise.
    for (int i = 0; i < 3; ++i) {
      const int other = mesh.neighbour[3 * f + i];
      if (other >= 0 && facing[std::size_t(other)] == facingHere) continue;
      // Edge a → b in the light-facing winding.
      glm::vec3 a = mesh.corners[3 * f + i], b = mesh.corners[3 * f + (i + 1) % 3];
      if (facingHere == kAway) std::swap(a, b);
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
