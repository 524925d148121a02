// Known answers for the cascade helpers of light_crop.h: split depths, frustum slices, the
// crop of a light to a set of points and the world size of a texel.
#include "testbed/technique/light_crop.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace testbed {
namespace {

// A sun travelling along −y over the square of half size 10 around the origin.
LightTransforms sun() {
  LightDesc d;
  d.type = LightType::Directional;
  d.direction = {0, -1, 0};
  d.extent = 10;
  return lightTransforms(d);
}

// A spot at (0, 10, 0) looking down, 90° wide, depths 1..100.
LightTransforms spot() {
  LightDesc d;
  d.eye = {0, 10, 0};
  d.target = {0, 0, 0};
  d.fovDegrees = 90;
  return lightTransforms(d, 1.0f, 100.0f, 0.0f);
}

glm::vec2 ndcOf(const glm::mat4& m, const glm::vec3& p) {
  const glm::vec4 clip = m * glm::vec4(p, 1.0f);
  return glm::vec2(clip) / clip.w;
}

TEST(LightCrop, PracticalSplitsBlendTheLogarithmicAndUniformSchemes) {
  const auto uniform = practicalSplits(1, 100, 2, 0.0);
  const auto logarithmic = practicalSplits(1, 100, 2, 1.0);
  const auto half = practicalSplits(1, 100, 2, 0.5);
  ASSERT_EQ(uniform.size(), 3u);
  EXPECT_DOUBLE_EQ(uniform[1], 50.5);
  EXPECT_NEAR(logarithmic[1], 10.0, 1e-12);
  EXPECT_NEAR(half[1], 30.25, 1e-12);
  for (const auto& s : {uniform, logarithmic, half}) {
    EXPECT_DOUBLE_EQ(s.front(), 1.0);
    EXPECT_NEAR(s.back(), 100.0, 1e-12);
  }
  // Four logarithmic splits of [1, 10⁴]: a decade each.
  const auto four = practicalSplits(1, 1e4, 4, 1.0);
  for (int i = 0; i <= 4; ++i) EXPECT_NEAR(four[i], std::pow(10.0, i), 1e-9 * std::pow(10.0, i));
}

TEST(LightCrop, FrustumSliceCornersLieOnTheDepthPlanes) {
  CameraDesc camera;
  camera.eye = {0, 0, 0};
  camera.target = {0, 0, -1};
  camera.fovYDegrees = 90;
  const auto c = cameraFrustumSlice(camera, 2.0f, 1.0f, 3.0f);
  // Depth 1: half height tan 45° = 1, half width 2; depth 3: three times that.
  EXPECT_NEAR(glm::distance(c[0], glm::vec3(-2, -1, -1)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(c[3], glm::vec3(2, 1, -1)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(c[4], glm::vec3(-6, -3, -3)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(c[7], glm::vec3(6, 3, -3)), 0.0f, 1e-5f);
}

TEST(LightCrop, CropSpreadsThePointsOverTheMapWithItsMargin) {
  // A 4×2 footprint off centre: x in [1, 5], z in [−2, 0]. Square crop: the larger side,
  // 4 units, spans 256 − 2 texels of a 256 map, centred on (3, −1).
  const std::vector<glm::vec3> points = {{1, 0, -2}, {5, 0, 0}, {3, 1, -1}};
  const LightTransforms light = sun();
  const glm::mat4 crop = cropMatrix(light.viewProjection(), points, 256);
  const glm::mat4 m = crop * light.viewProjection();
  EXPECT_NEAR(glm::length(ndcOf(m, {3, 0, -1})), 0.0f, 1e-5f) << "the footprint's centre maps to the map's";
  const float edge = 254.0f / 256.0f;
  const glm::vec2 a = ndcOf(m, {1, 0, -1}), b = ndcOf(m, {5, 0, -1});
  EXPECT_NEAR(std::max(std::abs(a.x), std::abs(a.y)), edge, 1e-5f);
  EXPECT_NEAR(std::max(std::abs(b.x), std::abs(b.y)), edge, 1e-5f);
  // Depth is the light's.
  const glm::vec4 z0 = light.viewProjection() * glm::vec4(3, 1, -1, 1), z1 = m * glm::vec4(3, 1, -1, 1);
  EXPECT_FLOAT_EQ(z0.z, z1.z);
  // The cropped light states the crop: half size 2·256/254, so a texel of 4/254 units.
  const LightTransforms cropped = croppedLight(light, points, 256);
  EXPECT_NEAR(cropped.extent, 2.0f * 256.0f / 254.0f, 1e-5f);
  EXPECT_NEAR(texelWorldSize(cropped.projection, glm::ivec2(256), 5.0).x, 4.0 / 254.0, 1e-6);
}

TEST(LightCrop, CropKeepsOnlyTheFootprintWithinTheBounds) {
  // Points over x in [−20, 20] (beyond the light's frustum, |x| ≤ 10) and a scene in
  // x ∈ [0, 2], z ∈ [0, 2]: the crop is the scene's 2×2 square.
  const std::vector<glm::vec3> points = {{-20, 0, -20}, {20, 0, 20}};
  WorldBounds scene;
  scene.add({0, 0, 0});
  scene.add({2, 1, 2});
  const LightTransforms cropped = croppedLight(sun(), points, 64, scene, 0);
  EXPECT_NEAR(cropped.extent, 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(ndcOf(cropped.viewProjection(), {1, 0, 1})), 0.0f, 1e-5f);
  // Without bounds the frustum clamps it: the whole map.
  EXPECT_NEAR(croppedLight(sun(), points, 64, {}, 0).extent, 10.0f, 1e-5f);
}

TEST(LightCrop, PerspectiveCropAndItsEquivalentFov) {
  // On the ground (depth 10 from the spot) the square x, z ∈ [−1, 1]: NDC half 0.1, so the
  // crop scales by 10 and the equivalent fov is 2·atan(tan 45° / 10).
  const std::vector<glm::vec3> points = {{-1, 0, -1}, {1, 0, 1}};
  const LightTransforms cropped = croppedLight(spot(), points, 100, {}, 0);
  EXPECT_NEAR(cropped.fovDegrees, glm::degrees(2.0f * std::atan(0.1f)), 1e-3f);
  const glm::vec2 corner = ndcOf(cropped.viewProjection(), {1, 0, 1});
  EXPECT_NEAR(std::abs(corner.x), 1.0f, 1e-4f);
  EXPECT_NEAR(std::abs(corner.y), 1.0f, 1e-4f);
  // A texel at depth 10: 2 units over 100 texels.
  EXPECT_NEAR(texelWorldSize(cropped.projection, glm::ivec2(100), 10.0).x, 0.02, 1e-6);
  // A point behind the spot: no crop.
  EXPECT_EQ(cropMatrix(spot().viewProjection(), std::vector<glm::vec3>{{0, 20, 0}, {1, 0, 1}}, 100), glm::mat4(1.0f));
}

TEST(LightCrop, TexelWorldSizeOfUncroppedLights) {
  // Orthographic: 2·extent / N at every depth; perspective: 2·d·tan(fov/2) / N.
  EXPECT_NEAR(texelWorldSize(sun().projection, glm::ivec2(1000), 7.0).x, 0.02, 1e-7);
  EXPECT_NEAR(texelWorldSize(spot().projection, glm::ivec2(1000, 500), 50.0).x, 0.1, 1e-6);
  EXPECT_NEAR(texelWorldSize(spot().projection, glm::ivec2(1000, 500), 50.0).y, 0.2, 1e-6);
}

}  // namespace
}  // namespace testbed
