// Image tests of the shared passes against analytic answers: a box over a plane, lit
// straight down by a directional light (shadow = the box's square) and by a spot light
// (shadow = the top face's square scaled by H / (H - h)). The G-buffer positions give each
// receiver pixel's world point, so every floor pixel is checked against the exact answer
// except those within a band of 1.5 shadow-map texels (projected onto the floor) of the
// analytic boundary, where nearest sampling may legitimately go either way.
#include <gtest/gtest.h>

#include <cmath>

#include "testbed/harness/frame_runner.h"
#include "testbed/scene/primitives.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"

namespace testbed {
namespace {

using test::boxOverPlane;

struct FloorCheck {
  int checked = 0, inShadowChecked = 0, mismatches = 0;
};

// Compares the technique's visibility on floor pixels with a `halfSide`-square shadow,
// over the part of the floor the shadow map covers (|x|, |z| < coverHalf).
FloorCheck checkFloor(const ImageF& visibility, const ImageF& positions, float halfSide, float coverHalf,
                      float band) {
  FloorCheck result;
  for (int y = 0; y < visibility.height; ++y) {
    for (int x = 0; x < visibility.width; ++x) {
      if (positions.at(x, y, 3) < 0.5f || std::abs(positions.at(x, y, 1)) > 1e-3f) continue;
      const float px = positions.at(x, y, 0), pz = positions.at(x, y, 2);
      // Distance to the square's outline (Chebyshev suffices for an axis-aligned square).
      const float distance = std::abs(std::max(std::abs(px), std::abs(pz)) - halfSide);
      if (distance < band || std::max(std::abs(px), std::abs(pz)) > coverHalf - band) continue;
      const bool expectShadow = std::abs(px) < halfSide && std::abs(pz) < halfSide;
      const bool shadow = visibility.at(x, y) < 0.5f;
      ++result.checked;
      result.inShadowChecked += expectShadow;
      result.mismatches += shadow != expectShadow;
    }
  }
  return result;
}

class ShadowMapAnalytic : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }

  static TechniqueRun run(FrameRunner& runner) { return test::runTechnique(runner, "sm"); }

  // The floor under `light` shows a `halfSide` square of shadow, exactly away from a band of
  // 1.5 texels around its outline, over the part of the floor (|x|, |z| < coverHalf) that
  // the `mapSize`² map covers (a texel: 2 · coverHalf / mapSize on the floor).
  static void expectSquareShadow(const LightDesc& light, int mapSize, float halfSide, float coverHalf) {
    const Scene scene = boxOverPlane(light);  // the runner keeps a reference
    FrameRunner runner(scene, test::renderSettings({640, 480}, mapSize));
    const TechniqueRun result = run(runner);
    const float texel = 2 * coverHalf / float(mapSize);
    const FloorCheck check = checkFloor(result.visibility, runner.positions(), halfSide, coverHalf, 1.5f * texel);
    EXPECT_GT(check.checked, 50000);
    EXPECT_GT(check.inShadowChecked, 2000);
    EXPECT_EQ(check.mismatches, 0);
  }
};

TEST_F(ShadowMapAnalytic, DirectionalLightCastsTheBoxSquare) {
  expectSquareShadow(test::directional({0, -1, 0}, 40), 512, 5.0f, 40);
}

TEST_F(ShadowMapAnalytic, SpotLightCastsTheScaledTopFace) {
  // The top face (y = 12) projects largest: half side 5 · 40 / 28. The 60° cone covers
  // |x|, |z| < 40·tan(30°) on the floor under the light (the map is square, the floor flat).
  expectSquareShadow(test::spot({0, 40, 0}, 60), 1024, 5.0f * 40.0f / 28.0f, 40.0f * std::tan(glm::radians(30.0f)));
}

TEST_F(ShadowMapAnalytic, OutsideTheSpotConeIsShadowed) {
  // The 30° cone covers |x|, |z| < 40·tan(15°) ≈ 10.7 on the floor.
  const Scene scene = boxOverPlane(test::spot({0, 40, 0}, 30));
  FrameRunner runner(scene, test::renderSettings({320, 240}, 256));
  const TechniqueRun result = run(runner);
  const ImageF& positions = runner.positions();
  int outside = 0;
  for (int y = 0; y < positions.height; ++y)
    for (int x = 0; x < positions.width; ++x) {
      if (positions.at(x, y, 3) < 0.5f || std::abs(positions.at(x, y, 1)) > 1e-3f) continue;
      if (std::max(std::abs(positions.at(x, y, 0)), std::abs(positions.at(x, y, 2))) < 12.0f) continue;
      ++outside;
      EXPECT_LT(result.visibility.at(x, y), 0.5f) << "lit outside the cone at pixel " << x << "," << y;
    }
  EXPECT_GT(outside, 10000);
}

TEST_F(ShadowMapAnalytic, ReceiversFacingAwayFromTheLightAreShadowed) {
  // Light from below the floor: the floor's upper side faces away, so nothing on it is lit
  // although no occluder lies between it and the light.
  const Scene scene = test::floorScene("plane-lit-from-below", test::directional({0, 1, 0}, 60));
  FrameRunner runner(scene, test::renderSettings({160, 120}, 256));
  const test::Receivers receivers = test::receiversOf(run(runner).visibility);
  EXPECT_EQ(receivers.fullyShadowed, receivers.count);
  EXPECT_GT(receivers.count, 1000);
}

TEST_F(ShadowMapAnalytic, GBufferHoldsWorldPositionsAndCoverage) {
  Scene scene = boxOverPlane(test::directional({0, -1, 0}, 10));
  scene.camera.eye = {0, 50, -0.001f};  // straight down at the origin
  RenderSettings settings;
  settings.size = {101, 101};
  FrameRunner runner(scene, settings);
  const ImageF& positions = runner.positions();
  // Centre pixel sees the box top (y = 12) at the origin.
  EXPECT_NEAR(positions.at(50, 50, 0), 0.0f, 0.3f);
  EXPECT_NEAR(positions.at(50, 50, 1), 12.0f, 1e-3f);
  EXPECT_NEAR(positions.at(50, 50, 2), 0.0f, 0.3f);
  // The 80×80 plane fills the view (50·tan(22.5°) ≈ 20.7 < 40): full coverage.
  for (int i = 0; i < positions.width * positions.height; ++i) ASSERT_EQ(positions.pixels[i * 4 + 3], 1.0f);
}

}  // namespace
}  // namespace testbed
