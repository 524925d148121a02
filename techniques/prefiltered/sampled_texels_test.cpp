// The CPU bound of the texels the pre-filtered visibility pass reads (sampled_texels.h)
// holds every receiver of the G-buffer on every bundled scene, without its margin: the
// 2×2 texels a bilinear lookup at the receiver's light-space uv reads lie inside it. The
// fractions of the map printed are what the scissored moments and blur passes cover.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "techniques/prefiltered/sampled_texels.h"
#include "testbed/harness/frame_runner.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

bool insideLightSpace(const glm::vec3& light) {
  return glm::all(glm::greaterThanEqual(light, glm::vec3(0.0f))) && glm::all(glm::lessThanEqual(light, glm::vec3(1.0f)));
}

class SampledTexels : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_F(SampledTexels, HoldEveryReceiversBilinearFootprint) {
  for (const std::string name : {"bunny", "dragon_sun", "fence", "stacked_occluders", "wall"}) {
    for (const glm::ivec2 size : {glm::ivec2(320, 180), glm::ivec2(1280, 720)}) {
      const int mapSize = 1024;
      const Scene scene = test::bundledScene(name);
      FrameRunner runner(scene, test::renderSettings(size, mapSize));
      const glm::mat4 camera = cameraTransforms(scene.camera, float(size.x) / float(size.y)).viewProjection();
      const glm::mat4 light = runner.light().viewProjection();
      const TexelRect rect = sampledTexels(objectBoxes(scene), camera, runner.light(), mapSize, 0);
      ASSERT_FALSE(rect.empty()) << name;
      int receivers = 0, outside = 0;
      const ImageF& positions = runner.positions();
      for (int i = 0; i < positions.width * positions.height; ++i) {
        const float* p = &positions.pixels[std::size_t(4 * i)];
        if (!(p[3] > 0.5f)) continue;
        // lightSpace() of receiver.glsl, in float as the GPU computes it.
        const glm::vec4 clip = light * glm::vec4(p[0], p[1], p[2], 1.0f);
        if (!(clip.w > 0.0f)) continue;
        const glm::vec3 uvz = glm::vec3(clip) / clip.w * 0.5f + 0.5f;
        if (!insideLightSpace(uvz)) continue;
        ++receivers;
        const glm::ivec2 first(glm::floor(glm::vec2(uvz) * float(mapSize) - 0.5f));
        const glm::ivec2 lo = glm::max(first, glm::ivec2(0)), hi = glm::min(first + 1, glm::ivec2(mapSize - 1));
        if (glm::any(glm::lessThan(lo, rect.min)) || glm::any(glm::greaterThan(hi, rect.max))) ++outside;
      }
      EXPECT_GT(receivers, 0) << name;
      EXPECT_EQ(outside, 0) << name << " " << size.x << "x" << size.y;
      const glm::ivec2 extent = rect.max - rect.min + 1;
      std::cout << name << " " << size.x << "x" << size.y << ": texels [" << rect.min.x << ", " << rect.max.x
                << "] x [" << rect.min.y << ", " << rect.max.y << "], "
                << 100.0 * double(extent.x) * double(extent.y) / double(mapSize * mapSize) << " % of the map\n";
    }
  }
}

}  // namespace
}  // namespace testbed
