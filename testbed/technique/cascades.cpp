#include "testbed/technique/cascades.h"

#include <algorithm>
#include <cmath>

namespace testbed {

std::array<double, 2> splitRange(const ShadowSetup& setup, const CameraDesc& camera, const WorldBounds& scene) {
  const double nearPlane = camera.nearPlane, farPlane = camera.farPlane;
  if (setup.fit == MapFit::Stable || scene.empty()) return {nearPlane, farPlane};
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  double nearest = farPlane, farthest = nearPlane;
  for (const glm::vec3& corner : scene.corners()) {
    const double depth = glm::dot(corner - camera.eye, forward);
    nearest = std::min(nearest, depth);
    farthest = std::max(farthest, depth);
  }
  nearest = std::clamp(nearest, nearPlane, farPlane);
  farthest = std::clamp(farthest, nearest, farPlane);
  return {nearest, std::max(farthest, nearest * 1.0001)};
}

SliceSphere sliceSphere(const CameraDesc& camera, float aspect, double nearDepth, double farDepth) {
  // A corner at view depth d lies √k·d off the axis, k = tan²(fov_x/2) + tan²(fov_y/2).
  const double tanY = std::tan(double(glm::radians(camera.fovYDegrees)) / 2), tanX = tanY * aspect;
  const double k = tanX * tanX + tanY * tanY;
  // Equal distances to a near and a far corner: k·n² + (c − n)² = k·f² + (f − c)².
  const double centre = (k + 1) * (farDepth + nearDepth) / 2;
  if (centre >= farDepth) return {farDepth, std::sqrt(k) * farDepth};
  return {centre, std::sqrt(k * farDepth * farDepth + (farDepth - centre) * (farDepth - centre))};
}

double snapToTexel(double value, double texel) { return std::floor(value / texel) * texel; }

LightTransforms stableLight(const LightTransforms& light, const glm::vec3& centre, double radius, int mapSize) {
  const double half = std::ceil(radius * 64) / 64;
  const double texel = 2 * half / mapSize;
  const glm::vec4 inView = light.view * glm::vec4(centre, 1.0f);
  const double x = snapToTexel(inView.x, texel), y = snapToTexel(inView.y, texel);
  // The light's orthographic projection with its x and y rows replaced: clip = (v − c)/half,
  // c/half = 2·(whole texels)/N exactly, so every frame's grid is the same world grid.
  LightTransforms out = light;
  glm::mat4& p = out.projection;
  p[0] = glm::vec4(float(1 / half), 0, p[0][2], p[0][3]);
  p[1] = glm::vec4(0, float(1 / half), p[1][2], p[1][3]);
  p[2][0] = 0;
  p[2][1] = 0;
  p[3][0] = float(-x / half);
  p[3][1] = float(-y / half);
  out.extent = float(half);
  return out;
}

std::vector<CascadeMap> fitCascades(const ShadowSetup& setup, const LightTransforms& light, const CameraDesc& camera,
                                    float aspect, const WorldBounds& scene, int mapSize) {
  const auto [nearDepth, farDepth] = splitRange(setup, camera, scene);
  const std::vector<double> splits = splitDepths(setup.splits, setup.lambda, nearDepth, farDepth, setup.cascades);
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  std::vector<CascadeMap> maps;
  for (int i = 0; i < setup.cascades; ++i) {
    CascadeMap map{.light = light, .split = {splits[i], splits[i + 1]}};
    if (setup.fit == MapFit::Stable) {
      const SliceSphere sphere = sliceSphere(camera, aspect, splits[i], splits[i + 1]);
      map.light = stableLight(light, camera.eye + forward * float(sphere.centreDepth), sphere.radius, mapSize);
    } else {
      const auto slice = cameraFrustumSlice(camera, aspect, float(splits[i]), float(splits[i + 1]));
      map.light = croppedLight(light, slice, mapSize, scene);
    }
    maps.push_back(map);
  }
  return maps;
}

}  // namespace testbed
