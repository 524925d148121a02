// The facing rule at grazing incidence (testbed/scene/view.h kFacingLimit): a receiver that
// meets the light at less than 1° is in shadow, in every technique and both ground truths,
// so a light almost (not exactly) parallel to a surface renders as an exactly parallel one
// does. Before the rule, the wall scene under a sun 0.006° off vertical gave silhouette-map
// 16 % mismatch where the exactly vertical sun gave 0.02 %: the wall's lit, edge-on front
// face was the technique's projection aliasing, not its shadow edges.
#include <gtest/gtest.h>

#include <cmath>


#include "testbed/metrics/metrics.h"
#include "testbed/scene/scene.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"

namespace testbed {
namespace {


constexpr double kPi = 3.14159265358979;

TEST(FacingRule, OneDegreeOfIncidenceIsTheLimit) {
  EXPECT_NEAR(kFacingLimit, std::sin(kPi / 180), 1e-9);
  LightTransforms sun;
  sun.orthographic = true;
  sun.direction = {0, -1, 0};  // straight down
  const glm::vec3 p(0, 0, 0);
  auto tilted = [](double degrees) {  // a normal meeting the sun at `degrees`
    const double a = degrees * kPi / 180;
    return glm::vec3(float(std::cos(a)), float(std::sin(a)), 0);
  };
  EXPECT_TRUE(facesLight(sun, p, {0, 1, 0}));
  EXPECT_TRUE(facesLight(sun, p, tilted(1.01)));
  EXPECT_FALSE(facesLight(sun, p, tilted(0.99)));
  EXPECT_FALSE(facesLight(sun, p, tilted(0.0)));   // edge-on
  EXPECT_FALSE(facesLight(sun, p, tilted(-5.0)));  // facing away
  LightTransforms spot;
  spot.position = {0, 10, 0};
  spot.direction = {0, -1, 0};
  EXPECT_TRUE(facesLight(spot, {3, 0, 0}, {0, 1, 0}));
  EXPECT_FALSE(facesLight(spot, {3, 10.01f, 0}, {0, 1, 0}));  // above the light's height
}

TEST(FacingRule, GroundTruthAndSmShadowAFloorLitBelowOneDegree) {
  test::sharedContext();
  for (const double elevation : {0.5, 2.0}) {
    SCOPED_TRACE(elevation);
    const Scene scene = test::floorUnderSun(elevation);
    FrameRunner runner(scene, test::renderSettings({160, 90}, 256));
    const test::Receivers truth = test::receiversOf(test::groundTruthVisibility(runner));
    const test::Receivers sm = test::receiversOf(test::runTechnique(runner, "sm").visibility);
    ASSERT_GT(truth.count, 1000);
    EXPECT_EQ(sm.count, truth.count);
    const int expectedShadowed = elevation < 1 ? truth.count : 0;
    EXPECT_EQ(truth.fullyShadowed, expectedShadowed);
    EXPECT_EQ(sm.fullyShadowed, expectedShadowed);
  }
}

// The reproduction: the bundled wall scene under a sun almost, or exactly, vertical.
Scene wallUnderSun(double tilt) {
  Scene scene = test::bundledScene("wall");
  scene.light = LightDesc{};
  scene.light.type = LightType::Directional;
  scene.light.direction = glm::normalize(glm::vec3(0, -1, float(tilt)));
  return scene;
}

TEST(FacingRule, AnAlmostVerticalSunRendersAsAVerticalOne) {
  test::sharedContext();
  const Scene vertical = wallUnderSun(0), almost = wallUnderSun(0.0001);
  FrameRunner a(vertical, test::renderSettings({320, 180}, 256));
  FrameRunner b(almost, test::renderSettings({320, 180}, 256));
  const ImageF truthA = test::groundTruthVisibility(a), truthB = test::groundTruthVisibility(b);
  for (const auto& technique : registeredTechniques()) {
    const std::string id = technique.info->id;
    if (id == "groundtruth") continue;
    SCOPED_TRACE(id);
    const double exact = computeErrorMetrics(test::runTechnique(a, id).visibility, truthA).mismatchPct;
    const double tilted = computeErrorMetrics(test::runTechnique(b, id).visibility, truthB).mismatchPct;
    // The two lights differ by 0.006°, yet their maps' texel grids do not coincide (the
    // light's up vector is picked anew for an exactly vertical one), so boundary pixels
    // move: up to 0.3 points for msm. The defect was 16 points (silhouette-map).
    EXPECT_LE(tilted, exact + 0.5);
  }
}

}  // namespace
}  // namespace testbed
