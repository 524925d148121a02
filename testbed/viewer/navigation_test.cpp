#include "testbed/viewer/navigation.h"

#include <cmath>

#include <gtest/gtest.h>

namespace testbed::viewer {
namespace {

CameraDesc camera() {
  CameraDesc c;
  c.eye = {0, 10, -30};
  c.target = {0, 0, 5};
  return c;
}

float distance(const CameraDesc& c) { return glm::length(c.eye - c.target); }
float elevationDegrees(glm::vec3 offset) { return glm::degrees(std::asin(glm::normalize(offset).y)); }

TEST(ViewerNavigation, OrbitKeepsTheDistanceAndFullTurnReturns) {
  CameraDesc c = camera();
  const CameraDesc start = c;
  for (int i = 0; i < 12; ++i) orbit(c, 30, 0);
  EXPECT_NEAR(distance(c), distance(start), 1e-3f);
  EXPECT_NEAR(glm::length(c.eye - start.eye), 0.0f, 1e-3f);
  EXPECT_EQ(c.target, start.target);
}

TEST(ViewerNavigation, PositivePitchRaisesTheEyeAndStopsShortOfThePole) {
  CameraDesc c = camera();
  const float before = elevationDegrees(c.eye - c.target);
  orbit(c, 0, 10);
  EXPECT_NEAR(elevationDegrees(c.eye - c.target), before + 10, 1e-2f);
  orbit(c, 0, 500);
  EXPECT_NEAR(elevationDegrees(c.eye - c.target), 89.0f, 1e-2f);
  EXPECT_NEAR(distance(c), distance(camera()), 1e-3f);
}

TEST(ViewerNavigation, ZoomScalesTheDistanceButNotBelowTheNearPlane) {
  CameraDesc c = camera();
  const float d = distance(c);
  zoom(c, 0.5f);
  EXPECT_NEAR(distance(c), 0.5f * d, 1e-3f);
  zoom(c, 1e-9f);
  EXPECT_NEAR(distance(c), c.nearPlane, 1e-4f);
}

TEST(ViewerNavigation, PanAndFlyMoveEyeAndTargetTogether) {
  CameraDesc c = camera();
  const glm::vec3 offset = c.eye - c.target;
  pan(c, {50, -20}, 600);
  EXPECT_NEAR(glm::length(c.eye - c.target - offset), 0.0f, 1e-4f);
  // The scene follows the drag, so the camera moves to its left: +x for a camera looking along +z.
  EXPECT_GT(c.target.x, 0.0f);
  const CameraDesc before = c;
  fly(c, {0, 0, 2});
  EXPECT_NEAR(glm::length(c.eye - before.eye), 2.0f, 1e-4f);
  EXPECT_NEAR(glm::dot(glm::normalize(c.eye - before.eye), glm::normalize(before.target - before.eye)), 1.0f, 1e-5f);
}

TEST(ViewerNavigation, LightOrbitTurnsASpotAroundItsTargetAndADirectionalDirection) {
  LightDesc spot;
  spot.eye = {0, 50, 50};
  spot.target = {0, 0, 0};
  orbitLight(spot, 90, 0);
  EXPECT_NEAR(glm::length(spot.eye), std::sqrt(5000.0f), 1e-2f);
  EXPECT_NEAR(spot.eye.y, 50.0f, 1e-3f);
  EXPECT_NEAR(spot.eye.x, 50.0f, 1e-2f);

  LightDesc sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(1, -2, 0));
  orbitLight(sun, 0, 10);  // towards the zenith: the direction gets steeper
  EXPECT_NEAR(glm::length(sun.direction), 1.0f, 1e-5f);
  EXPECT_LT(sun.direction.y, glm::normalize(glm::vec3(1, -2, 0)).y);
}

}  // namespace
}  // namespace testbed::viewer
