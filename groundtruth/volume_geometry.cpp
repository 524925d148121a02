#include "groundtruth/volume_geometry.h"

#include <algorithm>
#include <cmath>

namespace testbed {
namespace {

glm::vec4 planeThrough(const glm::vec3& normal, const glm::vec3& point) {
  const float length = glm::length(normal);
  if (length == 0.0f) return {0, 0, 0, 1};
  const glm::vec3 n = normal / length;
  return {n, -glm::dot(n, point)};
}

enum Facing : signed char { kNone = 0, kTowards = 1, kAway = -1 };

// The sides end on the far plane only if every one of them crosses it once, outwards, and
// not too obliquely (the far ends stay within 100× the plane's distance from the light):
// for a point light the whole mesh lies in front of the light along the plane's normal,
// and every point of the mesh's box lies before the plane.
bool farPlaneCutsEverySide(const VolumeMesh& mesh, const VolumeLight& light, const VolumeReach& reach) {
  if (!reach.bounded) return false;
  if (light.directional) {
    if (!(glm::dot(reach.farNormal, light.direction) > 0.01f)) return false;
  }
  const float lightAlong = light.directional ? 0.0f : glm::dot(reach.farNormal, light.position);
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner = boxCorner(mesh.lo, mesh.hi, k);
    const float along = glm::dot(reach.farNormal, corner);
    if (!(along < reach.farOffset)) return false;
    if (!light.directional && !(along - lightAlong > 0.01f * (reach.farOffset - lightAlong))) return false;
  }
  return true;
}

// Möller & Trumbore's segment–triangle test in double precision, widened by `margin` in the
// barycentric coordinates and the segment parameter so that grazing hits count.
bool segmentMeetsTriangle(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& a, const glm::dvec3& b,
                          const glm::dvec3& c, double margin) {
  const glm::dvec3 direction = to - from, e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return false;  // parallel to the plane (or degenerate): no crossing point
  const glm::dvec3 s = from - a;
  const double u = glm::dot(s, p) / det;
  if (u < -margin || u > 1.0 + margin) return false;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (v < -margin || u + v > 1.0 + margin) return false;
  const double t = glm::dot(e2, q) / det;
  return t >= -margin && t <= 1.0 + margin;
}

// The slab test: the parameter ranges inside each pair of planes overlap within [0, 1],
// widened by `margin` as segmentMeetsTriangle's is.
bool segmentMeetsBox(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& lo, const glm::dvec3& hi,
                     double margin) {
  double enter = -margin, leave = 1.0 + margin;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = to[axis] - from[axis];
    if (d == 0.0) {
      if (from[axis] < lo[axis] || from[axis] > hi[axis]) return false;
      continue;
    }
    double t0 = (lo[axis] - from[axis]) / d, t1 = (hi[axis] - from[axis]) / d;
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return false;
  }
  return true;
}

}  // namespace

VolumeMesh volumeMesh(MeshTopology topology) {
  VolumeMesh mesh;
  const std::size_t faces = topology.corners.size() / 3;
  mesh.normal.reserve(faces);
  mesh.centroid.reserve(faces);
  for (std::size_t f = 0; f < faces; ++f) {
    const glm::vec3 &a = topology.corners[3 * f], &b = topology.corners[3 * f + 1], &c = topology.corners[3 * f + 2];
    mesh.normal.push_back(glm::cross(b - a, c - a));
    mesh.centroid.push_back((a + b + c) / 3.0f);
  }
  if (!topology.corners.empty()) mesh.lo = mesh.hi = topology.corners.front();
  for (const glm::vec3& p : topology.corners) {
    mesh.lo = glm::min(mesh.lo, p);
    mesh.hi = glm::max(mesh.hi, p);
  }
  mesh.topology = std::move(topology);
  return mesh;
}

VolumeStats appendShadowVolume(const TriMesh& mesh, const VolumeLight& light, std::vector<VolumeVertex>& out,
                               const VolumeReach& reach) {
  return appendShadowVolume(volumeMesh(meshTopology(mesh)), light, out, reach);
}

VolumeStats appendShadowVolume(const VolumeMesh& volumeMesh, const VolumeLight& light, std::vector<VolumeVertex>& out,
                               const VolumeReach& reach) {
  const MeshTopology& mesh = volumeMesh.topology;
  VolumeStats stats;
  (mesh.closed ? stats.closedMeshes : stats.openMeshes) = 1;
  stats.bounded = farPlaneCutsEverySide(volumeMesh, light, reach);
  const std::size_t faces = mesh.corners.size() / 3;

  // Facing of each face, from its corners (not stored normals) so orientation is exact.
  std::vector<Facing> facing(faces, kNone);
  for (std::size_t f = 0; f < faces; ++f) {
    const glm::vec3& normal = volumeMesh.normal[f];
    if (normal == glm::vec3(0)) continue;
    const glm::vec3 towardsLight = light.directional ? -light.direction : light.position - volumeMesh.centroid[f];
    facing[f] = glm::dot(normal, towardsLight) > 0 ? kTowards : kAway;  // edge-on faces block nothing
  }

  // A point extruded away from the light to infinity, or to the far plane when bounded.
  auto atInfinity = [&](const glm::vec3& p) {
    return light.directional ? glm::vec4(light.direction, 0) : glm::vec4(p - light.position, 0);
  };
  auto farEnd = [&](const glm::vec3& p) {
    if (!stats.bounded) return atInfinity(p);
    const glm::vec3 away = light.directional ? light.direction : p - light.position;
    const float along = (reach.farOffset - glm::dot(reach.farNormal, p)) / glm::dot(reach.farNormal, away);
    return glm::vec4(p + along * away, 1);
  };
  auto emit = [&](const glm::vec4& p, const glm::vec4& q, const glm::vec4& r, const glm::vec4& plane,
                  float lightCap = 0.0f, float weight = 1.0f) {
    out.push_back({p, plane, lightCap, weight});
    out.push_back({q, plane, lightCap, weight});
    out.push_back({r, plane, lightCap, weight});
  };

  for (std::size_t f = 0; f < faces; ++f) {
    const Facing facingHere = facing[f];
    if (facingHere == kNone || (mesh.closed && facingHere == kAway)) continue;
    // Corners ordered so the triangle is counter-clockwise seen from the light.
    glm::vec3 corner[3] = {mesh.corners[3 * f], mesh.corners[3 * f + 1], mesh.corners[3 * f + 2]};
    if (facingHere == kAway) std::swap(corner[1], corner[2]);
    if (reach.lightCaps) {
      const glm::vec4 capPlane = planeThrough(glm::cross(corner[1] - corner[0], corner[2] - corner[0]), corner[0]);
      emit(glm::vec4(corner[0], 1), glm::vec4(corner[1], 1), glm::vec4(corner[2], 1), capPlane, 1.0f);
      ++stats.capTriangles;
    }
    if (reach.darkCaps && !light.directional) {  // a directional dark cap collapses to one point at infinity
      emit(atInfinity(corner[0]), atInfinity(corner[2]), atInfinity(corner[1]), glm::vec4(0, 0, 0, 1));
      ++stats.capTriangles;
    }
    // Side quads on the region's boundary: the neighbour is missing or faces otherwise.
    for (int i = 0; i < 3; ++i) {
      const int other = mesh.neighbour[3 * f + i];
      if (other >= 0 && facing[std::size_t(other)] == facingHere) continue;
      const bool twin = reach.twinSidesOnce && !mesh.closed && other >= 0 && facing[std::size_t(other)] == -facingHere;
      if (twin && facingHere == kAway) continue;  // drawn with the light-facing region's
      // Edge a → b in the light-facing winding.
      glm::vec3 a = mesh.corners[3 * f + i], b = mesh.corners[3 * f + (i + 1) % 3];
      if (facingHere == kAway) std::swap(a, b);
      const glm::vec3 away = light.directional ? light.direction : a - light.position;
      const glm::vec4 plane = planeThrough(glm::cross(a - b, away), a);
      const glm::vec4 a4(a, 1), b4(b, 1), aFar = farEnd(a), bFar = farEnd(b);
      emit(b4, a4, aFar, plane, 0.0f, twin ? 2.0f : 1.0f);
      emit(b4, aFar, bFar, plane, 0.0f, twin ? 2.0f : 1.0f);
      ++stats.sideQuads;
    }
  }
  return stats;
}

VolumeReach depthPassReach(const VolumeMesh& mesh, const VolumeLight& light, const glm::vec3& lo, const glm::vec3& hi) {
  // Candidates: the light's axis (a plane across all of its rays) and the box's six faces.
  const glm::vec3 candidates[7] = {light.direction, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const glm::vec3 centre = (mesh.lo + mesh.hi) * 0.5f;
  const glm::vec3 away = light.directional ? light.direction : centre - light.position;
  VolumeReach best{.lightCaps = false, .darkCaps = false, .bounded = false, .twinSidesOnce = true};
  float bestLength = INFINITY;
  for (const glm::vec3& normal : candidates) {
    VolumeReach reach{.lightCaps = false, .darkCaps = false, .bounded = true, .farNormal = normal, .twinSidesOnce = true};
    reach.farOffset = -INFINITY;
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 corner = boxCorner(lo, hi, k);
      reach.farOffset = std::max(reach.farOffset, glm::dot(normal, corner));
    }
    if (!farPlaneCutsEverySide(mesh, light, reach)) continue;
    // How far the side through the mesh's centre runs before it ends: the fill it costs.
    const float length = (reach.farOffset - glm::dot(normal, centre)) / glm::dot(normal, away) * glm::length(away);
    if (length < bestLength) {
      bestLength = length;
      best = reach;
    }
  }
  return best;
}

bool eyeMayBeInVolume(const VolumeMesh& mesh, const VolumeLight& light, const glm::vec3& eye, float reach) {
  const glm::dvec3 from(eye);
  const glm::dvec3 to = light.directional ? from - double(reach) * glm::dvec3(light.direction) : glm::dvec3(light.position);
  // A segment that misses the mesh's box, widened beyond the triangles' margins, meets none
  // of them.
  const glm::dvec3 widen(1e-3 * glm::length(glm::dvec3(mesh.hi - mesh.lo)) + 1e-3);
  constexpr double kMargin = 1e-4;
  if (!segmentMeetsBox(from, to, glm::dvec3(mesh.lo) - widen, glm::dvec3(mesh.hi) + widen, kMargin)) return false;
  const auto& corners = mesh.topology.corners;
  for (std::size_t f = 0; f < mesh.normal.size(); ++f) {
    if (mesh.normal[f] == glm::vec3(0)) continue;  // degenerate: no volume
    if (segmentMeetsTriangle(from, to, corners[3 * f], corners[3 * f + 1], corners[3 * f + 2], kMargin)) return true;
  }
  return false;
}

}  // namespace testbed
