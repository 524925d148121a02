#include "testbed/scene/light_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace testbed {
namespace {

using Point = glm::dvec3;  // light view space: x, y across, depth d = −z along the axis
// A half-space a·x + b·y + c·d + w ≥ 0 of light view space.
using Plane = glm::dvec4;

// The light's view: from the spot's eye, or (directional) from its target, looking along
// the light's travel direction; the same axes as lightTransforms().
glm::dmat4 lightView(const LightDesc& light) {
  if (light.type == LightType::Spot) {
    const glm::vec3 direction = glm::normalize(light.target - light.eye);
    return glm::dmat4(glm::lookAt(light.eye, light.target, stableUp(direction)));
  }
  const glm::vec3 direction = glm::normalize(light.direction);
  return glm::dmat4(glm::lookAt(light.target, light.target + direction, stableUp(direction)));
}

// The four side planes of the light's frustum (spot: also d ≥ 0, in front of the eye).
std::vector<Plane> sidePlanes(const LightDesc& light, double extent) {
  if (light.type == LightType::Spot) {
    const double t = std::tan(glm::radians(double(light.fovDegrees)) / 2);
    return {{-1, 0, t, 0}, {1, 0, t, 0}, {0, -1, t, 0}, {0, 1, t, 0}, {0, 0, 1, 0}};
  }
  return {{-1, 0, 0, extent}, {1, 0, 0, extent}, {0, -1, 0, extent}, {0, 1, 0, extent}};
}

double side(const Plane& plane, const Point& p) {
  return plane.x * p.x + plane.y * p.y + plane.z * p.z + plane.w;
}

// Sutherland–Hodgman: a triangle clipped by at most 5 planes has at most 8 corners.
using Polygon = std::vector<Point>;
void clip(Polygon& polygon, const Plane& plane, Polygon& scratch) {
  scratch.clear();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Point& a = polygon[i];
    const Point& b = polygon[(i + 1) % polygon.size()];
    const double sa = side(plane, a), sb = side(plane, b);
    if (sa >= 0) scratch.push_back(a);
    if ((sa >= 0) != (sb >= 0)) scratch.push_back(a + (b - a) * (sa / (sa - sb)));
  }
  polygon.swap(scratch);
}

}  // namespace

LightDepthSpan lightDepthSpan(const Scene& scene, const LightDesc& light, float extent) {
  const glm::dmat4 view = lightView(light);
  const std::vector<Plane> planes = sidePlanes(light, extent);
  LightDepthSpan span;
  span.nearest = std::numeric_limits<double>::infinity();
  span.farthest = -span.nearest;
  auto include = [&](const Point& p) {
    span.nearest = std::min(span.nearest, p.z);
    span.farthest = std::max(span.farthest, p.z);
    span.found = true;
  };
  std::vector<Point> points;
  Polygon polygon, scratch;
  for (const auto& object : scene.objects) {
    const TriMesh& mesh = object.mesh;
    points.clear();
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      const glm::dvec4 q = view * glm::dvec4(p[0], p[1], p[2], 1.0);
      points.push_back({q.x, q.y, -q.z});
    }
    for (const auto f : mesh.faces()) {
      polygon.clear();
      for (const auto v : mesh.fv_range(f)) polygon.push_back(points[v.idx()]);
      const bool inside = std::all_of(planes.begin(), planes.end(), [&](const Plane& plane) {
        return std::all_of(polygon.begin(), polygon.end(), [&](const Point& p) { return side(plane, p) >= 0; });
      });
      if (!inside)
        for (const Plane& plane : planes) {
          clip(polygon, plane, scratch);
          if (polygon.empty()) break;
        }
      for (const Point& p : polygon) include(p);
    }
  }
  return span;
}

float fittedDirectionalExtent(const Scene& scene, const LightDesc& light) {
  const glm::dmat4 view = lightView(light);
  double half = 0;
  for (const auto& object : scene.objects)
    for (const auto v : object.mesh.vertices()) {
      const auto& p = object.mesh.point(v);
      const glm::dvec4 q = view * glm::dvec4(p[0], p[1], p[2], 1.0);
      half = std::max({half, std::abs(q.x), std::abs(q.y)});
    }
  return float(half * (1 + 2 * kDepthMargin));
}

LightTransforms fittedLightTransforms(const Scene& scene) {
  const LightDesc& light = scene.light;
  if (!light.fit) return lightTransforms(light);
  if (light.type == LightType::Spot) {
    const LightDepthSpan span = lightDepthSpan(scene, light, 0);
    const double nearPlane = std::max(double(light.nearPlane), span.nearest * (1 - kDepthMargin));
    const double farPlane = std::min(double(light.farPlane), span.farthest * (1 + kDepthMargin));
    if (!span.found || !(float(farPlane) > float(nearPlane))) return lightTransforms(light);
    LightTransforms t = lightTransforms(light, float(nearPlane), float(farPlane), 0);
    t.fitted = true;
    return t;
  }
  float extent = light.extent > 0 ? light.extent : fittedDirectionalExtent(scene, light);
  if (!(extent > 0)) extent = 1;  // a scene flat along the light's rays: any square holds it
  const LightDepthSpan span = lightDepthSpan(scene, light, extent);
  if (!span.found) {
    LightDesc given = light;
    given.extent = extent;
    return lightTransforms(given);
  }
  // A relative margin of the span, and of the distance to the target, each side: a flat
  // scene seen head-on still gets a non-empty range.
  const double margin =
      kDepthMargin * std::max({span.farthest - span.nearest, std::abs(span.nearest), std::abs(span.farthest), 1e-3});
  LightTransforms t = lightTransforms(light, float(span.nearest - margin), float(span.farthest + margin), extent);
  t.fitted = true;
  return t;
}

double depthStepWorld(const LightTransforms& light, int depthBits, double viewDepth) {
  const double step = std::ldexp(1.0, -depthBits);
  const double n = light.nearPlane, f = light.farPlane;
  if (light.orthographic) return step * (f - n);
  return step * (f - n) * viewDepth * viewDepth / (f * n);
}

}  // namespace testbed
