// The separable blur's packed intermediate (blur.frag's BLUR_PACK, R32F and RG32F moments)
// against the plain one it replaced: equal bit for bit at kernel sizes 3 (the papers')
// and 17 (GI 2016 Table 5's widest), which the GLSL specification guarantees for blur.frag's
// `precise` sums on any implementation, on a map whose width is no multiple of the pack, with
// values over the exponential warps' range. The formats that do not pack run the plain
// path either way and are checked too. And the blur of a region (the scissor of
// sampled_texels.h) from moments that hold their values over reads(region) only, garbage
// elsewhere: the region's texels equal the whole map's blur bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "techniques/prefiltered/moments_pass.h"
#include "techniques/prefiltered/separable_blur.h"
#include "testbed/gl/render_target.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

constexpr glm::ivec2 kSize{75, 75};
const TexelRect kWhole{glm::ivec2(0), kSize - 1};

int components(GLenum format) { return format == GL_R32F ? 1 : format == GL_RG32F ? 2 : 4; }

// Random moments blurred by `blur`, read back as floats.
std::vector<float> blurred(SeparableBlur& blur, GLenum format, const std::vector<glm::vec4>& texels,
                           const std::vector<float>& weights, const TexelRect& region = kWhole) {
  RenderTarget moments;
  moments.ensure({.size = kSize, .color = format});
  glTextureSubImage2D(moments.color().id(), 0, 0, 0, kSize.x, kSize.y, GL_RGBA, GL_FLOAT, texels.data());
  blur.ensure(kSize, format, true);
  blur.run(moments.color(), moments.framebuffer(), weights, region);
  return moments.color().readFloats(components(format));
}

TEST(SeparableBlur, PackedIntermediateGivesThePlainResultBitForBit) {
  test::sharedContext();
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), exponent(-8.0f, 34.0f);
  for (const GLenum format : {GL_R32F, GL_RG32F, GL_RGBA32F, GL_RGBA16})
    for (const int size : {3, 17}) {
      std::vector<glm::vec4> texels(std::size_t(kSize.x) * kSize.y);
      for (auto& t : texels)
        for (int c = 0; c < 4; ++c)
          t[c] = format == GL_RGBA16 ? unit(random) : unit(random) * std::pow(10.0f, exponent(random));
      const std::vector<float> weights = MomentsPass::blurWeights(size);
      SeparableBlur packed, plain(false);
      const std::vector<float> fast = blurred(packed, format, texels, weights);
      const std::vector<float> reference = blurred(plain, format, texels, weights);
      ASSERT_EQ(fast.size(), reference.size());
      int differing = 0;
      for (std::size_t i = 0; i < fast.size(); ++i) differing += fast[i] != reference[i];
      EXPECT_EQ(differing, 0) << "format 0x" << std::hex << format << std::dec << ", kernel " << size;
      EXPECT_NE(fast, std::vector<float>(fast.size(), 0.0f));
    }
}

std::vector<glm::vec4> randomMoments(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<glm::vec4> texels(std::size_t(kSize.x) * kSize.y);
  for (auto& t : texels) t = glm::vec4(unit(random), unit(random), unit(random), unit(random));
  return texels;
}

TEST(SeparableBlur, RegionNeedsOnlyTheTexelsItReads) {
  test::sharedContext();
  std::mt19937 random(12);
  const std::vector<TexelRect> regions{{{0, 0}, {9, 4}}, {{31, 17}, {52, 40}}, {{66, 70}, {74, 74}}, {{5, 60}, {5, 60}}};
  for (const GLenum format : {GL_R32F, GL_RG32F, GL_RGBA32F, GL_RGBA16})
    for (const int size : {3, 17}) {
      const std::vector<glm::vec4> texels = randomMoments(random);
      const std::vector<float> weights = MomentsPass::blurWeights(size);
      SeparableBlur blur;
      const std::vector<float> whole = blurred(blur, format, texels, weights);
      for (const TexelRect& region : regions) {
        const TexelRect read = blur.reads(region, format, size / 2, kSize.x);
        std::vector<glm::vec4> partial = texels;
        for (int y = 0; y < kSize.y; ++y)
          for (int x = 0; x < kSize.x; ++x)
            if (x < read.min.x || x > read.max.x || y < read.min.y || y > read.max.y)
              partial[std::size_t(y * kSize.x + x)] = glm::vec4(format == GL_RGBA16 ? 1.0f : NAN);
        const std::vector<float> part = blurred(blur, format, partial, weights, region);
        const int channels = components(format);
        int differing = 0;
        for (int y = region.min.y; y <= region.max.y; ++y)
          for (int x = region.min.x; x <= region.max.x; ++x)
            for (int c = 0; c < channels; ++c) {
              const std::size_t i = std::size_t((y * kSize.x + x) * channels + c);
              differing += !(part[i] == whole[i]);
            }
        EXPECT_EQ(differing, 0) << "format 0x" << std::hex << format << std::dec << ", kernel " << size
                                << ", region at " << region.min.x << ", " << region.min.y;
      }
    }
}

}  // namespace
}  // namespace testbed
