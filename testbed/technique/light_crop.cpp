#include "testbed/technique/light_crop.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>


namespace testbed {

std::array<glm::vec3, 8> WorldBounds::corners() const {
  std::array<glm::vec3, 8> out;
  for (int i = 0; i < 8; ++i) out[i] = {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
  return out;
}

std::array<glm::vec3, 8> cameraFrustumSlice(const CameraDesc& camera, float aspect, float nearDepth, float farDepth) {
  // Back from the camera's view space, as cameraTransforms() builds it (scene/view.h).
  const glm::mat4 viewToWorld = glm::inverse(cameraTransforms(camera, aspect).view);
  const float tanY = std::tan(glm::radians(camera.fovYDegrees) / 2), tanX = tanY * aspect;
  std::array<glm::vec3, 8> out;
  int i = 0;
  for (const float depth : {nearDepth, farDepth})
    for (const float sy : {-1.0f, 1.0f})
      for (const float sx : {-1.0f, 1.0f})
        out[i++] = glm::vec3(viewToWorld * glm::vec4(sx * tanX * depth, sy * tanY * depth, -depth, 1.0f));
  return out;
}

namespace {

// The light-NDC xy box of `points`, clamped to the light's frustum; none if a point is behind
// a spot light.
std::optional<std::pair<glm::vec2, glm::vec2>> footprint(const glm::mat4& lightViewProjection,
                                                          std::span<const glm::vec3> points) {
  glm::vec2 lo(std::numeric_limits<float>::infinity()), hi(-std::numeric_limits<float>::infinity());
  for (const glm::vec3& p : points) {
    const glm::vec4 clip = lightViewProjection * glm::vec4(p, 1.0f);
    if (!(clip.w > 0.0f)) return std::nullopt;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  return std::pair{glm::clamp(lo, -1.0f, 1.0f), glm::clamp(hi, -1.0f, 1.0f)};
}

}  // namespace

glm::mat4 cropMatrix(const glm::mat4& lightViewProjection, std::span<const glm::vec3> points, int mapSize,
                     const WorldBounds& within, int marginTexels) {
  if (points.empty()) return glm::mat4(1.0f);
  auto box = footprint(lightViewProjection, points);
  if (box && !within.empty()) {
    const auto corners = within.corners();
    if (const auto scene = footprint(lightViewProjection, corners)) {
      box->first = glm::max(box->first, scene->first);
      box->second = glm::min(box->second, scene->second);
    }
  }
  if (!box || box->first.x > box->second.x || box->first.y > box->second.y) return glm::mat4(1.0f);
  const auto [lo, hi] = *box;
  const glm::vec2 centre = (lo + hi) * 0.5f;
  const float half = std::max(hi.x - lo.x, hi.y - lo.y) * 0.5f;
  // The footprint's half size covers mapSize − 2·margin texels of the map.
  const int inner = std::max(mapSize - 2 * marginTexels, 1);
  const float scale = float(inner) / (float(mapSize) * std::max(half, 1e-6f));
  // x' = s·(x − c·w), y' likewise, per clip coordinate, so the same C crops a perspective map.
  glm::mat4 crop(1.0f);
  crop[0][0] = scale;
  crop[1][1] = scale;
  crop[3][0] = -scale * centre.x;
  crop[3][1] = -scale * centre.y;
  return crop;
}

LightTransforms croppedLight(const LightTransforms& light, std::span<const glm::vec3> points, int mapSize,
                             const WorldBounds& within, int marginTexels) {
  const glm::mat4 crop = cropMatrix(light.viewProjection(), points, mapSize, within, marginTexels);
  LightTransforms out = light;
  out.projection = crop * light.projection;
  const float scale = crop[0][0];
  if (light.orthographic)
    out.extent = light.extent / scale;
  else
    out.fovDegrees = glm::degrees(2.0f * std::atan(std::tan(glm::radians(light.fovDegrees) / 2) / scale));
  return out;
}

glm::dvec2 texelWorldSize(const glm::mat4& projection, glm::ivec2 mapSize, double viewDepth) {
  // Clip w at view-space z = −viewDepth: P₂₃·z + P₃₃ (column, row).
  const double w = -double(projection[2][3]) * viewDepth + double(projection[3][3]);
  return {2.0 * w / (double(projection[0][0]) * mapSize.x), 2.0 * w / (double(projection[1][1]) * mapSize.y)};
}

std::vector<double> practicalSplits(double nearDepth, double farDepth, int count, double lambda) {
  std::vector<double> splits;
  for (int i = 0; i <= count; ++i) {
    const double t = double(i) / count;
    splits.push_back(lambda * nearDepth * std::pow(farDepth / nearDepth, t) +
                     (1 - lambda) * (nearDepth + (farDepth - nearDepth) * t));
  }
  return splits;
}

}  // namespace testbed
