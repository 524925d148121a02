#include "testbed/technique/parameter_binder.h"

#include <gtest/gtest.h>

#include "testbed/core/error.h"

namespace testbed {
namespace {

enum class Mode { Fast, Exact };

struct Demo {
  int kernel;
  bool bilinear;
  float bias;
  std::string visibility;
  Mode mode;
  struct Shared {
    double offset;
    void reflect(ParameterBinder& b) { b.real("offset", offset, 4.0, 0.0, 100.0, "shared offset"); }
  } shared;
  void reflect(ParameterBinder& b) {
    b.integer("kernel", kernel, 3, 1, 17, "kernel size").oddOnly();
    b.boolean("bilinear", bilinear, false, "bilinear weights");
    b.real("bias", bias, 0.25, -1.0, 1.0, "depth bias");
    b.choice("visibility", visibility, "conservative", {"conservative", "improved"}, "visibility");
    b.choice("mode", mode, Mode::Exact, {{"fast", Mode::Fast}, {"exact", Mode::Exact}}, "mode");
    shared.reflect(b);
  }
};

TEST(ParameterBinder, CollectsOneSpecPerDeclarationInOrder) {
  const auto specs = declaredParameters<Demo>();
  ASSERT_EQ(specs.size(), 6u);
  EXPECT_EQ(specs[0].name, "kernel");
  EXPECT_EQ(specs[0].type, ParameterType::Int);
  EXPECT_EQ(std::get<std::int64_t>(specs[0].defaultValue), 3);
  EXPECT_EQ(specs[0].min, 1);
  EXPECT_EQ(specs[0].max, 17);
  EXPECT_TRUE(specs[0].oddOnly);
  EXPECT_EQ(specs[0].help, "kernel size");
  EXPECT_FALSE(specs[1].oddOnly);
  EXPECT_EQ(specs[1].type, ParameterType::Bool);
  EXPECT_EQ(std::get<double>(specs[2].defaultValue), 0.25);
  EXPECT_EQ(specs[3].choices, (std::vector<std::string>{"conservative", "improved"}));
  // A choice bound to an enum declares its words and the default's word.
  EXPECT_EQ(specs[4].type, ParameterType::Choice);
  EXPECT_EQ(specs[4].choices, (std::vector<std::string>{"fast", "exact"}));
  EXPECT_EQ(std::get<std::string>(specs[4].defaultValue), "exact");
  EXPECT_EQ(specs[5].name, "offset");
  for (const auto& spec : specs) EXPECT_EQ(parameterSpecProblem(spec), "") << spec.name;
}

TEST(ParameterBinder, AssignsDefaultsAndGivenValuesToTheMembers) {
  const auto specs = declaredParameters<Demo>();
  Demo defaults{};
  bindParameters(resolveParameters("demo", specs, {}), defaults);
  EXPECT_EQ(defaults.kernel, 3);
  EXPECT_FALSE(defaults.bilinear);
  EXPECT_EQ(defaults.bias, 0.25f);
  EXPECT_EQ(defaults.visibility, "conservative");
  EXPECT_EQ(defaults.mode, Mode::Exact);
  EXPECT_EQ(defaults.shared.offset, 4.0);

  Demo set{};
  bindParameters(resolveParameters("demo", specs,
                                   {{"kernel", "7"}, {"bilinear", "true"}, {"bias", "-0.1"},
                                    {"visibility", "improved"}, {"mode", "fast"}, {"offset", "2.5"}}),
                 set);
  EXPECT_EQ(set.kernel, 7);
  EXPECT_TRUE(set.bilinear);
  EXPECT_EQ(set.bias, static_cast<float>(-0.1));  // the double narrowed once, as a cast does
  EXPECT_EQ(set.visibility, "improved");
  EXPECT_EQ(set.mode, Mode::Fast);
  EXPECT_EQ(set.shared.offset, 2.5);
  // Validation stays resolveParameters': the odd-only flag travels in the spec.
  EXPECT_THROW(resolveParameters("demo", specs, {{"kernel", "4"}}), InputError);
}

struct DefaultWithoutWord {
  Mode mode;
  void reflect(ParameterBinder& b) { b.choice("mode", mode, Mode::Exact, {{"fast", Mode::Fast}}, "mode"); }
};

TEST(ParameterBinder, AChoiceDefaultWithoutAWordIsASpecProblem) {
  const auto specs = declaredParameters<DefaultWithoutWord>();
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(parameterSpecProblem(specs[0]), "default '' is not among its choices");
}

}  // namespace
}  // namespace testbed
