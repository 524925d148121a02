#pragma once
// Camera and light moves of the viewer, shared by the mouse/keyboard and by scripts so a
// scripted `orbit 30 0` is the same move as the equivalent drag. Angles in degrees.
#include <glm/glm.hpp>

#include "testbed/scene/scene.h"

namespace testbed::viewer {

// Turns the eye around the target: `yaw` about the camera's up axis, `pitch` about its
// right axis (positive looks down on the target). Pitch stops 1° short of the up axis so
// the view never flips; the eye–target distance is kept.
void orbit(CameraDesc& camera, float yawDegrees, float pitchDegrees);
// Moves eye and target together within the image plane; `pixels` as the mouse moves them
// (x right, y down) on a view `viewHeight` pixels tall, so the target follows the cursor.
void pan(CameraDesc& camera, glm::vec2 pixels, float viewHeight);
// Scales the eye–target distance by `factor` (< 1 moves closer), never below 1e-3 of it
// nor nearer than the near plane.
void zoom(CameraDesc& camera, float factor);
// Moves eye and target by `step` in camera space: x right, y up, z forward (world units).
void fly(CameraDesc& camera, glm::vec3 step);
// Spot: turns the light's eye around its target like orbit(); directional: turns its
// direction the same way (the target stays the centre of its shadow-map cube).
void orbitLight(LightDesc& light, float yawDegrees, float pitchDegrees);

}  // namespace testbed::viewer
