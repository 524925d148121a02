// ShadowMapPass::Parameters declares the polygon offset once: the papers' defaults, or the
// ones a technique asks for, with the same names, ranges and help.
#include "testbed/render/shadow_map_pass.h"

#include <gtest/gtest.h>

#include <variant>

namespace testbed {
namespace {

struct PapersOffsets {
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) { shadowMap.reflect(b); }
};

struct OwnOffsets {
  ShadowMapPass::Parameters shadowMap;
  void reflect(ParameterBinder& b) { shadowMap.reflect(b, {.factor = 1.5, .units = 4}); }
};

double defaultOf(const ParameterSpec& spec) { return std::get<double>(spec.defaultValue); }

TEST(ShadowMapPassParameters, ReflectTakesOverriddenDefaultsAndKeepsTheRest) {
  const auto papers = declaredParameters<PapersOffsets>();
  const auto own = declaredParameters<OwnOffsets>();
  ASSERT_EQ(papers.size(), 2u);
  ASSERT_EQ(own.size(), 2u);
  EXPECT_EQ(papers[0].name, "offset_factor");
  EXPECT_DOUBLE_EQ(defaultOf(papers[0]), 4.0);
  EXPECT_DOUBLE_EQ(defaultOf(papers[1]), 20.0);
  EXPECT_DOUBLE_EQ(defaultOf(own[0]), 1.5);
  EXPECT_DOUBLE_EQ(defaultOf(own[1]), 4.0);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(own[i].name, papers[i].name);
    EXPECT_EQ(own[i].min, papers[i].min);
    EXPECT_EQ(own[i].max, papers[i].max);
    EXPECT_EQ(own[i].help, papers[i].help);
  }
}

}  // namespace
}  // namespace testbed
