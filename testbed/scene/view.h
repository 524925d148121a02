#pragma once
// Camera and light transforms. The light's matrices are the shadow map's: a square
// perspective frustum for spot lights, an orthographic cube for directional ones.
#include <glm/glm.hpp>

#include "testbed/scene/scene.h"

namespace testbed {

struct ViewProjection {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::mat4 viewProjection() const { return projection * view; }
};

ViewProjection cameraTransforms(const CameraDesc& camera, float aspect);

struct LightTransforms : ViewProjection {
  bool orthographic = false;
  glm::vec3 position{0};   // spot: the light's eye; directional: unused
  glm::vec3 direction{0};  // unit vector the light travels along (spot: eye → target)
  float nearPlane = 1, farPlane = 1000;
};

LightTransforms lightTransforms(const LightDesc& light);

// An up vector that is not parallel to `forward`, for lookAt.
glm::vec3 stableUp(const glm::vec3& forward, const glm::vec3& preferred = {0, 1, 0});

}  // namespace testbed
