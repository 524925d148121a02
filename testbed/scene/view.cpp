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
  if (light.type == LightType::Spot) return lightTransforms(light, light.nearPlane, light.farPlane, 0.0f);
  return lightTransforms(light, -light.extent, light.extent, light.extent);
}

LightTransforms lightTransforms(const LightDesc& light, float nearPlane, float farPlane, float extent) {
  LightTransforms t;
  if (light.type == LightType::Spot) {
    t.position = light.eye;
    t.direction = glm::normalize(light.target - light.eye);
    t.nearPlane = nearPlane;
    t.farPlane = farPlane;
    t.fovDegrees = light.fovDegrees;
    t.view = glm::lookAt(light.eye, light.target, stableUp(t.direction));
    t.projection = glm::perspective(glm::radians(light.fovDegrees), 1.0f, nearPlane, farPlane);
  } else {
    // The eye sits on the near plane, so the depth range is [0, far − near] from it.
    t.orthographic = true;
    t.direction = glm::normalize(light.direction);
    t.position = light.target + t.direction * nearPlane;
    t.nearPlane = 0.0f;
    t.farPlane = farPlane - nearPlane;
    t.extent = extent;
    t.view = glm::lookAt(t.position, t.position + t.direction, stableUp(t.direction));
    t.projection = glm::ortho(-extent, extent, -extent, extent, t.nearPlane, t.farPlane);
  }
  return t;
}

bool insideLightFrustum(const LightTransforms& light, const glm::vec3& world) {
  const glm::vec4 clip = light.viewProjection() * glm::vec4(world, 1.0f);
  if (!(clip.w > 0.0f)) return false;  // behind a spot light (or on its eye plane)
  const glm::vec3 p = glm::vec3(clip) / clip.w * 0.5f + 0.5f;
  return p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f && p.x <= 1.0f && p.y <= 1.0f && p.z <= 1.0f;
}

bool facesLight(const LightTransforms& light, const glm::vec3& world, const glm::vec3& normal) {
  // Same float operations, same order, as towardsLight()/facesAwayFromLight() in GLSL.
  const glm::vec3 towards = light.orthographic ? -light.direction : glm::normalize(light.position - world);
  return glm::dot(normal, towards) > kFacingLimit;
}

}  // namespace testbed
