#include "testbed/viewer/navigation.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "testbed/scene/view.h"

namespace testbed::viewer {
namespace {

constexpr float kPoleMarginDegrees = 1.0f;

// `offset` (from the pivot) turned by yaw about `up` and pitch about the horizontal axis,
// with pitch clamped so the result stays kPoleMarginDegrees away from ±up.
glm::vec3 turn(glm::vec3 offset, glm::vec3 up, float yawDegrees, float pitchDegrees) {
  up = glm::normalize(up);
  const float length = glm::length(offset);
  const glm::vec3 direction = offset / length;
  // Elevation of the offset above the plane normal to `up`, in degrees.
  const float elevation = glm::degrees(std::asin(std::clamp(glm::dot(direction, up), -1.0f, 1.0f)));
  const float limit = 90.0f - kPoleMarginDegrees;
  const float pitch = std::clamp(elevation + pitchDegrees, -limit, limit) - elevation;
  const glm::vec3 right = glm::normalize(glm::cross(stableUp(direction, up), direction));
  glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), glm::radians(yawDegrees), up);
  rotation = rotation * glm::rotate(glm::mat4(1.0f), glm::radians(-pitch), right);
  return glm::normalize(glm::vec3(rotation * glm::vec4(direction, 0.0f))) * length;
}

struct CameraFrame {
  glm::vec3 forward, right, up;
};

CameraFrame frameOf(const CameraDesc& camera) {
  const glm::vec3 forward = glm::normalize(camera.target - camera.eye);
  const glm::vec3 right = glm::normalize(glm::cross(forward, stableUp(forward, camera.up)));
  return {forward, right, glm::cross(right, forward)};
}

}  // namespace

void orbit(CameraDesc& camera, float yawDegrees, float pitchDegrees) {
  camera.eye = camera.target + turn(camera.eye - camera.target, camera.up, yawDegrees, pitchDegrees);
}

void pan(CameraDesc& camera, glm::vec2 pixels, float viewHeight) {
  const CameraFrame f = frameOf(camera);
  const float distance = glm::length(camera.target - camera.eye);
  const float worldPerPixel = 2.0f * distance * std::tan(glm::radians(camera.fovYDegrees) * 0.5f) / viewHeight;
  const glm::vec3 move = (-pixels.x * f.right + pixels.y * f.up) * worldPerPixel;
  camera.eye += move;
  camera.target += move;
}

void zoom(CameraDesc& camera, float factor) {
  const glm::vec3 offset = camera.eye - camera.target;
  const float distance = glm::length(offset);
  const float wanted = std::max({distance * factor, distance * 1e-3f, camera.nearPlane});
  camera.eye = camera.target + offset * (wanted / distance);
}

void fly(CameraDesc& camera, glm::vec3 step) {
  const CameraFrame f = frameOf(camera);
  const glm::vec3 move = step.x * f.right + step.y * f.up + step.z * f.forward;
  camera.eye += move;
  camera.target += move;
}

void orbitLight(LightDesc& light, float yawDegrees, float pitchDegrees) {
  const glm::vec3 up(0, 1, 0);
  if (light.type == LightType::Spot) {
    light.eye = light.target + turn(light.eye - light.target, up, yawDegrees, pitchDegrees);
  } else {
    // The direction points from the light into the scene: turn the way back to the light.
    light.direction = -glm::normalize(turn(-light.direction, up, yawDegrees, pitchDegrees));
  }
}

}  // namespace testbed::viewer
