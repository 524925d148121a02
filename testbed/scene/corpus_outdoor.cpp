#include "testbed/scene/corpus_outdoor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace testbed {
namespace {

using namespace corpus_detail;

constexpr double kOutdoorCameraFar = 2.2 * kOutdoorGroundHalf;  // the whole ground from its edge
constexpr int kWalkFrames = 48;
constexpr int kWalkFps = 24;

// A mesh fitted to `size`, turned upright by one of the three axes' choices and about y,
// resting on the ground at `foot`; its top height through `top`.
Json placeCaster(const MeshInfo& mesh, double size, glm::dvec3 foot, Draw& draw, double& top) {
  const double rx = std::array<double, 3>{0, -90, 90}[draw.index(3)], ry = r4(draw.between(0, 360));
  const glm::dvec3 extent = mesh.hi - mesh.lo;
  const double scale = size / std::max({extent.x, extent.y, extent.z});
  const glm::dvec3 centre = (mesh.lo + mesh.hi) * 0.5;
  const glm::dmat4 rotation = glm::rotate(glm::dmat4(1), glm::radians(ry), {0, 1, 0}) *
                              glm::rotate(glm::dmat4(1), glm::radians(rx), {1, 0, 0});
  double lo = 1e300, hi = -1e300;
  for (const auto& p : mesh.points) {
    const double y = (rotation * glm::dvec4((p - centre) * scale, 1)).y;
    lo = std::min(lo, y);
    hi = std::max(hi, y);
  }
  const glm::dvec3 translate = foot + glm::dvec3(0, -lo, 0);
  top = r4(translate.y) + hi;
  return {{"mesh", mesh.reference}, {"fit", r4(size)}, {"rotate", vec({rx, ry, 0})}, {"translate", vec(translate)}};
}

// The half side of a square light footprint holding the ground and everything up to `top`.
double sunExtent(const glm::dvec3& direction, double top) {
  double extent = 0;
  for (double x : {-kOutdoorGroundHalf, kOutdoorGroundHalf})
    for (double y : {0.0, top})
      for (double z : {-kOutdoorGroundHalf, kOutdoorGroundHalf}) {
        const glm::dvec3 p(x, y, z);
        extent = std::max(extent, glm::length(p - glm::dot(p, direction) * direction));
      }
  return extent * 1.02;
}

glm::dvec3 onGround(glm::dvec3 p, double margin) {
  const double limit = kOutdoorGroundHalf - margin;
  return {std::clamp(p.x, -limit, limit), p.y, std::clamp(p.z, -limit, limit)};
}

}  // namespace

SceneSample sampleOutdoorScene(const CorpusOptions& options, std::size_t index, int attempt,
                               const std::vector<MeshInfo>& meshes) {
  const std::uint64_t stream = splitmix64(options.seed ^ splitmix64(index) ^ 0x6F7574646F6F72ull);  // "outdoor"
  Draw draw(attempt == 0 ? stream : splitmix64(stream + std::uint64_t(attempt)));

  // The camera: near one edge of the ground, a few units up, looking across it and a
  // little down.
  const double height = draw.between(1.7, 8), yaw = draw.between(-20, 20), fov = draw.between(45, 65);
  const glm::dvec3 eye(draw.between(-60, 60), height, -0.85 * kOutdoorGroundHalf);
  const glm::dvec3 forward = glm::normalize(onSphere(0, yaw) - glm::dvec3(0, draw.between(0.02, 0.1), 0));
  const glm::dvec3 ahead = glm::normalize(glm::dvec3(forward.x, 0, forward.z));
  const glm::dvec3 right(ahead.z, 0, -ahead.x);
  const double aspect = double(options.image.x) / options.image.y;
  const double halfWidth = std::tan(glm::radians(fov) / 2) * aspect;

  // Casters from near to far, sized with their distance.
  Json objects = Json::array();
  objects.push_back({{"primitive", "plane"}, {"size", {2 * kOutdoorGroundHalf, 2 * kOutdoorGroundHalf}}});
  const int casters = 4 + int(draw.index(4));
  std::vector<double> distances;
  for (int i = 0; i < casters; ++i) distances.push_back(draw.logBetween(kOutdoorNearest, kOutdoorFarthest));
  std::sort(distances.begin(), distances.end());
  double top = 0;
  Json placed = Json::array();
  for (const double distance : distances) {
    const MeshInfo& mesh = meshes[draw.index(meshes.size())];
    const double size = distance * draw.between(0.1, 0.25);
    const double side = draw.between(-0.7, 0.7) * halfWidth * distance;
    const glm::dvec3 foot = onGround(glm::dvec3(eye.x, 0, eye.z) + distance * ahead + side * right, size);
    double casterTop = 0;
    objects.push_back(placeCaster(mesh, size, foot, draw, casterTop));
    top = std::max(top, casterTop);
    placed.push_back({{"mesh", mesh.named}, {"distance", r4(distance)}, {"size", r4(size)}});
  }

  // The sun, low: shadows long on the ground.
  const double elevation = r4(draw.between(kOutdoorMinSunDeg, kOutdoorMaxSunDeg)), azimuth = r4(draw.between(0, 360));
  const glm::dvec3 toSun = onSphere(elevation, azimuth);
  const double radiusDeg = r4(draw.between(0.25, 1.0));  // the sun's is about 0.27°
  const Json light = {{"type", "directional"},
                      {"direction", vec(-toSun)},
                      {"target", vec({0, 0, 0})},
                      {"extent", r4(sunExtent(-toSun, top))},
                      {"radius", radiusDeg}};
  const glm::dvec3 target = eye + 40.0 * forward;
  Json scene = {{"name", ""},
                {"comment", ""},
                {"camera", {{"eye", vec(eye)}, {"target", vec(target)}, {"fov_y", r4(fov)}, {"near", 0.3}, {"far", kOutdoorCameraFar}}},
                {"light", light},
                {"objects", objects}};

  // Half the scenes walk the camera forward: receivers change cascade between frames.
  const bool walk = draw.chance(0.5);
  const double walked = walk ? draw.between(10, 40) : 0;
  if (walk)
    scene["animation"] = {
        {"frames", kWalkFrames},
        {"fps", kWalkFps},
        {"camera",
         {{{"frame", 0}, {"eye", vec(eye)}, {"target", vec(target)}},
          {{"frame", kWalkFrames - 1}, {"eye", vec(eye + walked * ahead)}, {"target", vec(target + walked * ahead)}}}}};

  char number[32];
  std::snprintf(number, sizeof number, "%03zu", index);
  const std::string name = number + std::string("-outdoor");
  scene["name"] = name;
  scene["comment"] = "Generated by testbed corpus --kind outdoor --seed " + std::to_string(options.seed) + " (scene " +
                     std::to_string(index) + (attempt > 0 ? ", draw " + std::to_string(attempt) : "") + "): " +
                     std::to_string(casters) + " casters from " + Json(r4(distances.front())).dump() + " to " +
                     Json(r4(distances.back())).dump() + " units ahead, sun at elevation " + Json(elevation).dump() +
                     " deg, camera " + Json(r4(height)).dump() + " units up" +
                     (walk ? ", walking " + Json(r4(walked)).dump() + " units forward" : "") + ".";
  SceneSample sample;
  sample.scene = scene;
  sample.manifest = {{"file", name + ".json"},
                     {"kind", "outdoor"},
                     {"casters", placed},
                     {"light", "directional"},
                     {"elevation_deg", elevation},
                     {"azimuth_deg", azimuth},
                     {"radius_deg", radiusDeg},
                     {"camera_height", r4(height)},
                     {"walk", walk ? Json(r4(walked)) : Json(nullptr)}};
  return sample;
}

}  // namespace testbed
