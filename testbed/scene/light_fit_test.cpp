// Light set-up on the CPU: fitted depth ranges hold the scene's geometry and stay within
// the scene's limits, the outside-the-frustum convention on each of the six sides (and
// behind a spot light) for both light types, the depth step's world size, and the
// parser's rejection of numerically degenerate light values.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/scene/light_fit.h"
#include "testbed/scene/primitives.h"
#include "tests/test_scenes.h"

namespace testbed {
namespace {

using nlohmann::json;

// Every vertex of the scene inside the fitted frustum (in its footprint for a directional
// light, whose depth range must then hold it).
void expectAllInside(const Scene& scene, const LightTransforms& light) {
  for (const auto& object : scene.objects)
    for (const auto v : object.mesh.vertices()) {
      const auto& p = object.mesh.point(v);
      EXPECT_TRUE(insideLightFrustum(light, {p[0], p[1], p[2]})) << p[0] << " " << p[1] << " " << p[2];
    }
}

TEST(LightFit, SpotRangeHugsTheGeometryWithinTheSceneLimits) {
  LightDesc light = test::spot({0, 60, 0}, 30);  // straight down; the floor's centre seen
  light.nearPlane = 0.01f;
  light.farPlane = 1e5f;
  const Scene scene = test::boxOverPlane(light);
  const LightTransforms t = fittedLightTransforms(scene);
  EXPECT_TRUE(t.fitted);
  // The box top at y = 12 lies 48 from the eye; the floor, square to the axis, at 60.
  EXPECT_NEAR(t.nearPlane, 48 * (1 - kDepthMargin), 1e-3);
  EXPECT_NEAR(t.farPlane, 60 * (1 + kDepthMargin), 1e-3);

  Scene limited = scene;
  limited.light.nearPlane = 50;  // the box top lies in front: clipped (outside → shadow)
  limited.light.farPlane = 55;
  const LightTransforms l = fittedLightTransforms(limited);
  EXPECT_FLOAT_EQ(l.nearPlane, 50);
  EXPECT_FLOAT_EQ(l.farPlane, 55);

  Scene given = scene;
  given.light.fit = false;
  const LightTransforms g = fittedLightTransforms(given);
  EXPECT_FALSE(g.fitted);
  EXPECT_FLOAT_EQ(g.nearPlane, 0.01f);
  EXPECT_FLOAT_EQ(g.farPlane, 1e5f);
}

TEST(LightFit, SpotWithNothingInsideKeepsTheGivenRange) {
  LightDesc light = test::spot({0, 60, 0}, 30);
  light.target = {0, 120, 0};  // looking up, away from the floor
  const LightTransforms t = fittedLightTransforms(test::floorScene("up", light));
  EXPECT_FALSE(t.fitted);
  EXPECT_FLOAT_EQ(t.nearPlane, 1);
  EXPECT_FLOAT_EQ(t.farPlane, 1000);
}

TEST(LightFit, DirectionalExtentAndDepthHoldEveryVertex) {
  for (const float elevation : {2.0f, 10.0f, 45.0f, 90.0f}) {
    SCOPED_TRACE(elevation);
    const float e = glm::radians(elevation);
    LightDesc light = test::directional({std::cos(e), -std::sin(e), 0.3f * std::cos(e)});
    light.extent = 0;  // fitted
    const Scene scene = test::boxOverPlane(light);
    const LightTransforms t = fittedLightTransforms(scene);
    EXPECT_TRUE(t.fitted);
    EXPECT_GT(t.extent, 0);
    expectAllInside(scene, t);
    // Tight: the fitted extent is no larger than the floor's half diagonal plus margin.
    EXPECT_LE(t.extent, 40 * std::sqrt(2.0f) * (1 + 2 * kDepthMargin) + 1e-3f);
  }
}

TEST(LightFit, DirectionalGivenExtentSmallerThanTheReceiversKeepsItsSquare) {
  LightDesc light = test::directional({1, -0.1f, 0}, 10);
  const LightTransforms t = fittedLightTransforms(test::boxOverPlane(light));
  EXPECT_FLOAT_EQ(t.extent, 10);
  // Every occluder upstream of a receiver inside the square lies in the depth range.
  EXPECT_TRUE(insideLightFrustum(t, {0, 9, 0}));
  EXPECT_TRUE(insideLightFrustum(t, {40, 0, 0}));
  EXPECT_TRUE(insideLightFrustum(t, {-40, 0, 0}));
  EXPECT_FALSE(insideLightFrustum(t, {0, 0, 20}));
}

// Points just beyond each of the six sides, and behind a spot light, are outside.
void expectSides(const LightTransforms& t, const glm::vec3& centre, const glm::vec3& right, const glm::vec3& up,
                 const glm::vec3& forward, float halfX, float halfY, float nearDepth, float farDepth) {
  const glm::vec3 middle = centre + forward * (0.5f * (nearDepth + farDepth));
  EXPECT_TRUE(insideLightFrustum(t, middle));
  EXPECT_FALSE(insideLightFrustum(t, middle + right * (halfX * 1.01f))) << "right";
  EXPECT_FALSE(insideLightFrustum(t, middle - right * (halfX * 1.01f))) << "left";
  EXPECT_FALSE(insideLightFrustum(t, middle + up * (halfY * 1.01f))) << "top";
  EXPECT_FALSE(insideLightFrustum(t, middle - up * (halfY * 1.01f))) << "bottom";
  EXPECT_FALSE(insideLightFrustum(t, centre + forward * (nearDepth * 0.99f - 1e-3f))) << "near";
  EXPECT_FALSE(insideLightFrustum(t, centre + forward * (farDepth * 1.01f + 1e-3f))) << "far";
  EXPECT_TRUE(insideLightFrustum(t, centre + forward * (nearDepth * 1.01f + 1e-3f)));
  EXPECT_TRUE(insideLightFrustum(t, centre + forward * (farDepth * 0.99f)));
}

TEST(LightFrustumConvention, SpotSixSidesAndBehind) {
  LightDesc light = test::spot({0, 50, 0}, 60);
  light.nearPlane = 10;
  light.farPlane = 40;
  const LightTransforms t = lightTransforms(light);
  const glm::vec3 forward = t.direction, up = glm::normalize(glm::vec3(glm::inverse(t.view)[1]));
  const glm::vec3 right = glm::cross(forward, up);
  const float half = 25 * std::tan(glm::radians(30.0f));  // at the middle depth 25
  expectSides(t, light.eye, right, up, forward, half, half, 10, 40);
  EXPECT_FALSE(insideLightFrustum(t, light.eye - forward * 20.0f)) << "behind";
  EXPECT_FALSE(insideLightFrustum(t, light.eye)) << "at the eye";
}

TEST(LightFrustumConvention, DirectionalSixSides) {
  LightDesc light = test::directional({0.3f, -1, 0.2f}, 8);
  const LightTransforms t = lightTransforms(light);  // cube of half size 8 around the target
  const glm::vec3 forward = t.direction, up = glm::normalize(glm::vec3(glm::inverse(t.view)[1]));
  const glm::vec3 right = glm::cross(forward, up);
  expectSides(t, t.position, right, up, forward, 8, 8, 0, 16);
}

TEST(LightFit, DepthStepWorldFollowsTheRange) {
  LightDesc light = test::spot({0, 10, 0}, 45);
  light.nearPlane = 1;
  light.farPlane = 1000;
  const LightTransforms wide = lightTransforms(light);
  // The papers' range at 16 bits: one step 150 units away is ≈ 0.34 world units.
  EXPECT_NEAR(depthStepWorld(wide, 16, 150), 150.0 * 150 * 999 / 1000 / 65536, 1e-9);
  light.nearPlane = 100;
  light.farPlane = 200;
  EXPECT_LT(depthStepWorld(lightTransforms(light), 16, 150), 0.01);
  const LightTransforms ortho = lightTransforms(test::directional({0, -1, 0}, 50));
  EXPECT_NEAR(depthStepWorld(ortho, 24, 0), 100.0 / (1 << 24), 1e-12);
}

// The parser checks the values as given; messages name the field and the reason.
json sceneWithLight(const json& light) {
  return {{"camera", {{"eye", {0, 10, -20}}, {"target", {0, 0, 0}}}},
          {"light", light},
          {"objects", json::array({{{"primitive", "plane"}, {"size", {10, 10}}}})}};
}

void expectRejected(const json& light, const std::string& key, const std::string& reason) {
  try {
    parseScene(sceneWithLight(light), "s.json");
    ADD_FAILURE() << "accepted " << light.dump();
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("s.json: " + key + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

TEST(LightParser, RejectsNumericallyDegenerateValues) {
  expectRejected({{"type", "spot"}, {"eye", {0, 10, 0}}, {"target", {0, 0, 0}}, {"near", 30}, {"far", 1e38}},
                 "light.far", "not finite and invertible");
  expectRejected({{"type", "spot"}, {"eye", {0, 0, 0}}, {"target", {1e-30, 0, 0}}}, "light.target",
                 "too close to light.eye");
  expectRejected({{"type", "spot"}, {"eye", {0, 10, 0}}, {"target", {0, 0, 0}}, {"fov", 1e-38}}, "light.fov",
                 "not finite");
  expectRejected({{"type", "directional"}, {"direction", {0, -1, 0}}, {"extent", 1e38}}, "light.extent",
                 "too large");
  expectRejected({{"type", "directional"}, {"direction", {0, -1, 0}}, {"fit", false}}, "light.extent",
                 "missing required key");
  expectRejected({{"type", "spot"}, {"eye", {0, 10, 0}}, {"target", {0, 0, 0}}, {"fit", 1}}, "light.fit",
                 "expected true or false");
}

TEST(LightParser, FitDefaultsOnAndExtentIsOptional) {
  const Scene fitted = parseScene(sceneWithLight({{"type", "directional"}, {"direction", {0, -1, 0}}}), "s.json");
  EXPECT_TRUE(fitted.light.fit);
  EXPECT_EQ(fitted.light.extent, 0.0f);
  const Scene given = parseScene(
      sceneWithLight({{"type", "spot"}, {"eye", {0, 10, 0}}, {"target", {0, 0, 0}}, {"fit", false}}), "s.json");
  EXPECT_FALSE(given.light.fit);
  EXPECT_FALSE(fittedLightTransforms(given).fitted);
}

}  // namespace
}  // namespace testbed
