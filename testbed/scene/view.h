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
  glm::vec3 position{0};   // spot: the light's eye; directional: the orthographic eye
  glm::vec3 direction{0};  // unit vector the light travels along (spot: eye → target)
  float nearPlane = 1, farPlane = 1000;  // view depths along `direction` from `position`
  float fovDegrees = 0;                  // spot: the square frustum's full angle
  float extent = 0;                      // directional: half size of the square footprint
  bool fitted = false;                   // the depth range (and extent) fitted to the scene
};

// The light's transforms from its description as given: a spot's near/far, a directional
// light's cube of half size `extent` around its target (depth range [0, 2·extent]). The
// harness uses fittedLightTransforms() (light_fit.h), which calls this when fitting is off.
LightTransforms lightTransforms(const LightDesc& light);
// The same with an explicit depth range; directional: depths from the plane through
// `light.target`, so the eye sits at target + nearPlane·direction and near becomes 0.
LightTransforms lightTransforms(const LightDesc& light, float nearPlane, float farPlane, float extent);

// The one convention for receivers outside the light's frustum, on any of its six sides or
// behind a spot light: they are in shadow, in every technique and every ground truth. This
// is the CPU twin of lightSpace()/insideLightFrustum() in glsl/receiver.glsl (same float
// operations, same order), for the ray caster and the tests.
bool insideLightFrustum(const LightTransforms& light, const glm::vec3& world);

// The facing rule, shared by every technique and every ground truth: a receiver is in
// shadow when its (geometric) normal faces away from the light or meets the light at less
// than 1°, i.e. dot(normal, towards light) ≤ kFacingLimit = sin 1°. Edge-on
// and nearly edge-on receivers alike: a surface within a degree of the light's rays has a
// footprint in the shadow map of a fraction of a texel, so every projective technique's
// answer there is projection aliasing (Lambert shading makes it at most 1.7 % of full
// light either way), and counting it would measure that instead of the shadow's edges.
inline constexpr float kFacingLimit = 0.0174524064f;  // sin(1°)
// True when a receiver at `world` with unit geometric normal `normal` is lit by the facing
// rule (the CPU twin of facesAwayFromLight() in glsl/receiver.glsl).
bool facesLight(const LightTransforms& light, const glm::vec3& world, const glm::vec3& normal);

// An up vector that is not parallel to `forward`, for lookAt.
glm::vec3 stableUp(const glm::vec3& forward, const glm::vec3& preferred = {0, 1, 0});

}  // namespace testbed
