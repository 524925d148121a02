// The family's registration, parameter validation, blur kernel and measured memory.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "techniques/prefiltered/moments_pass.h"
#include "testbed/harness/frame_runner.h"
#include "testbed/core/error.h"
#include "testbed/scene/scene.h"
#include "testbed/technique/registry.h"
#include "tests/gl_fixture.h"

namespace testbed {
namespace {

const char* const kIds[] = {"vsm", "esm", "evsm", "msm"};

ParameterSet resolve(const std::string& id, const std::map<std::string, std::string>& raw) {
  return resolveParameters(id, findTechnique(id).info->parameters, raw);
}

TEST(PrefilteredParameters, FourFilteredPluginsShareTheBlurParameters) {
  for (const char* id : kIds) {
    const TechniqueInfo& info = *findTechnique(id).info;
    EXPECT_EQ(info.family, "prefiltered") << id;
    EXPECT_EQ(info.output, OutputKind::Filtered) << id;
    EXPECT_FALSE(info.citation.empty()) << id;
    const ParameterSet defaults = resolve(id, {});
    EXPECT_EQ(defaults.getInt("blur"), 3) << id;
    EXPECT_FALSE(defaults.getBool("mips")) << id;
  }
  EXPECT_EQ(resolve("esm", {}).getFloat("exponent"), 80.0);
  EXPECT_EQ(resolve("evsm", {}).getFloat("positive_exponent"), 40.0);
  EXPECT_EQ(resolve("evsm", {}).getFloat("negative_exponent"), 5.0);
  EXPECT_EQ(resolve("msm", {}).getChoice("storage"), "16");
  EXPECT_EQ(resolve("msm", {}).getFloat("moment_bias"), 1e-4);
  EXPECT_EQ(resolve("msm", {}).getFloat("depth_bias"), 5e-5);
  EXPECT_EQ(resolve("vsm", {}).getFloat("bleed_reduction"), 0.0);
}

TEST(PrefilteredParameters, BadValuesAreRejected) {
  const std::vector<std::pair<std::string, std::map<std::string, std::string>>> bad{
      {"vsm", {{"blur", "4"}}},                  // even kernel
      {"vsm", {{"blur", "0"}}},
      {"msm", {{"blur", "19"}}},                 // beyond 17
      {"vsm", {{"mips", "maybe"}}},
      {"vsm", {{"min_variance", "-1e-6"}}},
      {"vsm", {{"bleed_reduction", "1"}}},       // linstep(1, 1, p) divides by zero
      {"esm", {{"exponent", "89"}}},             // exp(89) overflows a float
      {"esm", {{"exponent", "0"}}},
      {"evsm", {{"positive_exponent", "43"}}},   // exp(2·43) leaves no room in Chebyshev's sum
      {"evsm", {{"negative_exponent", "100"}}},
      {"evsm", {{"moments", "3"}}},
      {"msm", {{"storage", "8"}}},
      {"msm", {{"storage", "float"}}},
      {"msm", {{"moment_bias", "0.5"}}},
      {"msm", {{"exponent", "80"}}},             // another technique's parameter
  };
  for (const auto& [id, raw] : bad)
    EXPECT_THROW(resolve(id, raw), InputError) << id << " " << raw.begin()->first << "=" << raw.begin()->second;
  EXPECT_NO_THROW(resolve("vsm", {{"blur", "17"}, {"mips", "true"}}));  // GI 2016 Table 5's 17×17
  EXPECT_NO_THROW(resolve("evsm", {{"moments", "2"}, {"positive_exponent", "42"}}));
  EXPECT_NO_THROW(resolve("msm", {{"storage", "32"}, {"blur", "1"}}));
}

TEST(PrefilteredParameters, BlurWeightsAreTheBinomialGaussian) {
  EXPECT_EQ(MomentsPass::blurWeights(1), std::vector<float>{1.0f});
  EXPECT_EQ(MomentsPass::blurWeights(3), (std::vector<float>{0.5f, 0.25f}));  // [1 2 1] / 4
  const auto five = MomentsPass::blurWeights(5);                              // [1 4 6 4 1] / 16
  ASSERT_EQ(five.size(), 3u);
  EXPECT_FLOAT_EQ(five[0], 6.0f / 16);
  EXPECT_FLOAT_EQ(five[1], 4.0f / 16);
  EXPECT_FLOAT_EQ(five[2], 1.0f / 16);
  const auto fifteen = MomentsPass::blurWeights(15);
  ASSERT_EQ(fifteen.size(), 8u);
  double total = fifteen[0];
  for (std::size_t k = 1; k < fifteen.size(); ++k) total += 2.0 * fifteen[k];
  EXPECT_NEAR(total, 1.0, 1e-6);
  // The widest, 17 (GI 2016 Table 5): C(16, 8 + k) / 2^16, exact in float.
  const std::vector<float> binomial{12870, 11440, 8008, 4368, 1820, 560, 120, 16, 1};
  std::vector<float> expected;
  for (const float c : binomial) expected.push_back(c / 65536.0f);
  EXPECT_EQ(MomentsPass::blurWeights(17), expected);
}

TEST(PrefilteredParameters, MemoryIsTheMomentsTheirMipsThePingPongAndTheDepth) {
  test::sharedContext();
  const Scene scene = test::bundledScene("wall");
  FrameRunner runner(scene, test::renderSettings({64, 36}, 256));  // depth 16-bit by default
  auto bytes = [&](const std::string& id, const std::map<std::string, std::string>& raw) {
    return runner.run(findTechnique(id), resolve(id, raw)).memoryBytes;
  };
  const std::uint64_t texels = 256 * 256, depth = 2 * texels;
  std::uint64_t chainTexels = 0;  // levels 1.. of a 256² chain
  for (int side = 128; side >= 1; side /= 2) chainTexels += std::uint64_t(side) * side;

  EXPECT_EQ(bytes("vsm", {}), 8 * texels + 8 * texels + depth);  // RG32F moments + ping-pong
  EXPECT_EQ(bytes("vsm", {{"blur", "1"}}), 8 * texels + depth);  // no blur: no ping-pong
  EXPECT_EQ(bytes("vsm", {{"mips", "true"}}), 8 * (texels + chainTexels) + 8 * texels + depth);
  EXPECT_EQ(bytes("esm", {}), 4 * texels + 4 * texels + depth);           // R32F
  EXPECT_EQ(bytes("evsm", {}), 16 * texels + 16 * texels + depth);        // RGBA32F
  EXPECT_EQ(bytes("evsm", {{"moments", "2"}}), 8 * texels + 8 * texels + depth);
  EXPECT_EQ(bytes("msm", {}), 8 * texels + 8 * texels + depth);           // RGBA16
  EXPECT_EQ(bytes("msm", {{"storage", "32"}}), 16 * texels + 16 * texels + depth);
}

TEST(PrefilteredParameters, EveryTechniqueTimesItsThreePasses) {
  test::sharedContext();
  const Scene scene = test::bundledScene("wall");
  FrameRunner runner(scene, test::renderSettings({64, 36}, 128));
  for (const char* id : kIds) {
    const TechniqueRun run = runner.run(findTechnique(id), resolve(id, {}));
    EXPECT_EQ(run.times.order, (std::vector<std::string>{"moments", "blur", "visibility"})) << id;
  }
}

}  // namespace
}  // namespace testbed
