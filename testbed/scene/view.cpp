#include "testbed/scene/view.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace testbed {

glm::vec3 stableUp(const glm::vec3& forward, const glm::vec3& preferred) {
  const glm::vec3 f = glm::normalize(forward);
  if (std::abs(glm::dot(f, glm::normalize(preferred))) < 0.99f) return preferred;
  return std::abs(f.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
}

ViewProjection cameraTransforms(const CameraDesc& camera, float aspect) {
  ViewProjection vp;
  vp.view = glm::lookAt(camera.eye, camera.target, stableUp(camera.target - camera.eye, camera.up));
  vp.projection = glm::perspective(glm::radians(camera.fovYDegrees), aspect, camera.nearPlane,
                                   camera.farPlane);
  return vp;
}

LightTransforms lightTransforms(const LightDesc& light) {
  LightTransforms t;
  if (light.type == LightType::Spot) {
    t.position = light.eye;
    t.direction = glm::normalize(light.target - light.eye);
    t.nearPlane = light.nearPlane;
    t.farPlane = light.farPlane;
    t.view = glm::lookAt(light.eye, light.target, stableUp(t.direction));
    t.projection = glm::perspective(glm::radians(light.fovDegrees), 1.0f, light.nearPlane, light.farPlane);
  } else {
    // The eye sits `extent` behind the target, so the depth range [0, 2·extent] covers
    // the cube of half size `extent` around the target.
    t.orthographic = true;
    t.direction = glm::normalize(light.direction);
    const glm::vec3 eye = light.target - t.direction * light.extent;
    t.position = eye;
    t.nearPlane = 0.0f;
    t.farPlane = 2.0f * light.extent;
    t.view = glm::lookAt(eye, light.target, stableUp(t.direction));
    t.projection = glm::ortho(-light.extent, light.extent, -light.extent, light.extent,
                              t.nearPlane, t.farPlane);
  }
  return t;
}

}  // namespace testbed
