#pragma once
// Small scenes built in code for image tests with analytic answers, shared by the tests of
// the core passes, the ground truths and the techniques.
#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "testbed/scene/primitives.h"
#include "testbed/scene/scene.h"

namespace testbed::test {

inline TriMesh translated(TriMesh mesh, OpenMesh::Vec3f offset) {
  for (auto v : mesh.vertices()) mesh.point(v) += offset;
  mesh.update_normals();
  return mesh;
}

inline LightDesc directional(glm::vec3 direction, float extent = 40) {
  LightDesc light;
  light.type = LightType::Directional;
  light.direction = glm::normalize(direction);
  light.target = {0, 0, 0};
  light.extent = extent;
  return light;
}

inline LightDesc spot(glm::vec3 eye, float fov) {
  LightDesc light;
  light.type = LightType::Spot;
  light.eye = eye;
  light.target = {0, 0, 0};
  light.fovDegrees = fov;
  return light;
}

// An 80×80 floor at y = 0 seen obliquely from above.
inline Scene floorScene(const std::string& name, const LightDesc& light) {
  Scene scene;
  scene.name = name;
  scene.camera.eye = {28, 34, -30};
  scene.camera.target = {0, 0, 0};
  scene.light = light;
  scene.objects.push_back({"plane", makePlane(80, 80)});
  return scene;
}

// Box from y = 10 to 12, x and z in [−5, 5], over the floor.
inline Scene boxOverPlane(const LightDesc& light) {
  Scene scene = floorScene(light.type == LightType::Spot ? "box-over-plane-spot" : "box-over-plane", light);
  scene.objects.push_back({"box", translated(makeBox(10, 2, 10), {0, 11, 0})});
  return scene;
}

// A 40 × 40 floor alone under a sun `elevationDeg` above it, read as a scene file is: no
// occluder, so whatever a technique shadows there is its own doing (acne, the facing rule).
inline Scene floorUnderSun(double elevationDeg) {
  const double e = elevationDeg * 3.14159265358979 / 180;
  const nlohmann::json scene = {
      {"name", "floor"},
      {"camera", {{"eye", {0, 30, -40}}, {"target", {0, 0, 0}}}},
      {"light", {{"type", "directional"}, {"direction", {std::cos(e), -std::sin(e), 0}}}},
      {"objects", nlohmann::json::array({{{"primitive", "plane"}, {"size", {40, 40}}}})},
  };
  return parseScene(scene, "floor.json");
}

}  // namespace testbed::test
