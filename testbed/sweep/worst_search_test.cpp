// The worst-case search's bookkeeping without rendering: configurations land where the
// point says, the same seed draws the same points, the budget is the number of points,
// and on a figure with one planted peak the search ends near it.
#include <cmath>

#include <gtest/gtest.h>

#include "testbed/scene/camera_check.h"
#include "testbed/sweep/worst_search.h"

namespace testbed {
namespace {

Scene baseScene(LightType type) {
  Scene scene;
  scene.camera.eye = {0, 30, -40};
  scene.camera.target = {0, 0, 0};
  scene.light.type = type;
  scene.light.eye = {0, 40, 0};
  scene.light.target = {0, 0, 0};
  return scene;
}

TEST(WorstSearch, ConfigurationsPlaceLightCameraAndMapAsThePointSays) {
  WorstSpace space;
  space.elevationMin = 10;
  space.elevationMax = 50;
  space.mapSizes = {128, 256};
  WorstPoint p;
  p.u = {0.5, 0.25, 0.0, 0.0, 0.5, 0.75};  // elevation 30°, azimuth 90°, camera at 10° and distance × 1
  const WorstConfiguration sun = configurationAt(baseScene(LightType::Directional), space, p);
  EXPECT_DOUBLE_EQ(sun.lightElevation, 30.0);
  EXPECT_NEAR(sun.light.direction.y, -0.5f, 1e-6);  // travels down at 30°
  EXPECT_NEAR(sun.light.direction.z, -std::cos(M_PI / 6), 1e-6);
  EXPECT_EQ(sun.shadowMap, 256);
  const WorstConfiguration spot = configurationAt(baseScene(LightType::Spot), space, p);
  EXPECT_NEAR(glm::length(spot.light.eye - spot.light.target), 40.0f, 1e-4);  // keeps its distance
  EXPECT_NEAR(spot.light.eye.y, 20.0f, 1e-4);
  EXPECT_NEAR(glm::length(spot.camera.eye - spot.camera.target), 50.0f, 1e-4);
  EXPECT_NEAR(spot.camera.eye.y, 50.0f * std::sin(M_PI / 18), 1e-4);
  space.moveCamera = false;
  EXPECT_EQ(configurationAt(baseScene(LightType::Spot), space, p).camera, baseScene(LightType::Spot).camera);
}

// The orbit's distance range (0.5–1.5 times the scene's) is cut at 95 % of the far plane:
// with the camera 50 away and far 60, the farthest point stands 57 away, the nearest 25,
// and each passes the scene parser's camera checks.
TEST(WorstSearch, TheOrbitStaysWithinTheFarPlane) {
  Scene scene = baseScene(LightType::Directional);
  scene.camera.farPlane = 60;
  WorstPoint p;
  for (double u : {0.0, 0.5, std::nextafter(1.0, 0.0)}) {
    p.u = {0.5, 0.5, 0.3, 0.5, u, 0.0};
    const WorstConfiguration c = configurationAt(scene, WorstSpace{}, p);
    const float distance = glm::length(c.camera.eye - c.camera.target);
    EXPECT_NEAR(distance, 25.0f + float(u) * 32.0f, 1e-3) << u;
    EXPECT_NO_THROW(checkCamera(c.camera, "scene.json")) << u;
  }
}

// A figure peaking at elevation coordinate 0.1 and map index coordinate 0.9.
double planted(const WorstPoint& p) { return -std::pow(p.u[0] - 0.1, 2) - std::pow(p.u[5] - 0.9, 2); }

TEST(WorstSearch, SameSeedSamePointsAndTheBudgetIsThePointCount) {
  WorstSearch a(7, 10), b(7, 10), c(8, 10);
  std::size_t count = 0;
  while (!a.done()) {
    const WorstPoint p = a.next(), q = b.next(), r = c.next();
    EXPECT_EQ(p.u, q.u);
    EXPECT_NE(p.u, r.u);
    a.report(p, planted(p));
    b.report(q, planted(q));
    c.report(r, planted(r));
    ++count;
  }
  EXPECT_EQ(count, 10u);
  const auto worst = a.worst(3);
  ASSERT_EQ(worst.size(), 3u);
  EXPECT_GE(worst[0].figure, worst[1].figure);
  EXPECT_GE(worst[1].figure, worst[2].figure);
}

TEST(WorstSearch, RefinementClimbsToAPlantedPeak) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    WorstSearch search(seed, 80);
    while (!search.done()) {
      const WorstPoint p = search.next();
      search.report(p, planted(p));
    }
    const WorstCase best = search.worst(1).front();
    EXPECT_NEAR(best.point.u[0], 0.1, 0.05) << "seed " << seed;
    EXPECT_NEAR(best.point.u[5], 0.9, 0.05) << "seed " << seed;
    EXPECT_GE(best.evaluation, 40u) << "refinement, not the random half, found it (seed " << seed << ")";
  }
}

}  // namespace
}  // namespace testbed
