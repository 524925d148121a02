#include "testbed/technique/parameters.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/technique/registry.h"

namespace testbed {
namespace {

const std::vector<ParameterSpec> kSpecs = {
    ParameterSpec::real("bias", 0.0, -1.0, 1.0, "depth bias"),
    ParameterSpec::integer("kernel", 3, 1, 17, "kernel size"),
    ParameterSpec::boolean("bilinear", false, "bilinear weights"),
    ParameterSpec::choice("visibility", "conservative", {"conservative", "improved"}, "visibility"),
};

std::string parameterError(const std::map<std::string, std::string>& raw) {
  try {
    resolveParameters("demo", kSpecs, raw);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Parameters, DefaultsFillEveryDeclaredName) {
  const ParameterSet set = resolveParameters("demo", kSpecs, {});
  EXPECT_EQ(set.getFloat("bias"), 0.0);
  EXPECT_EQ(set.getInt("kernel"), 3);
  EXPECT_FALSE(set.getBool("bilinear"));
  EXPECT_EQ(set.getChoice("visibility"), "conservative");
  EXPECT_EQ(set.values().size(), kSpecs.size());
}

TEST(Parameters, ParsesEachType) {
  const ParameterSet set = resolveParameters(
      "demo", kSpecs, {{"bias", "-0.25"}, {"kernel", "7"}, {"bilinear", "true"}, {"visibility", "improved"}});
  EXPECT_EQ(set.getFloat("bias"), -0.25);
  EXPECT_EQ(set.getInt("kernel"), 7);
  EXPECT_TRUE(set.getBool("bilinear"));
  EXPECT_EQ(set.getChoice("visibility"), "improved");
  EXPECT_EQ(set.toJson()["kernel"], 7);
}

TEST(Parameters, RejectsBadValuesNamingTheAssignment) {
  EXPECT_NE(parameterError({{"nope", "1"}}).find("--set nope=1: technique 'demo' has no parameter 'nope'"),
            std::string::npos);
  EXPECT_NE(parameterError({{"nope", "1"}}).find("bias, kernel, bilinear, visibility"), std::string::npos);
  EXPECT_NE(parameterError({{"bias", "abc"}}).find("--set bias=abc: expected a number"), std::string::npos);
  EXPECT_NE(parameterError({{"bias", "nan"}}).find("not a finite number"), std::string::npos);
  EXPECT_NE(parameterError({{"bias", "inf"}}).find("not a finite number"), std::string::npos);
  EXPECT_NE(parameterError({{"bias", "2"}}).find("out of range"), std::string::npos);
  EXPECT_NE(parameterError({{"kernel", "2.5"}}).find("expected an integer"), std::string::npos);
  EXPECT_NE(parameterError({{"kernel", "18"}}).find("out of range [1, 17]"), std::string::npos);
  EXPECT_NE(parameterError({{"kernel", ""}}).find("expected an integer"), std::string::npos);
  EXPECT_NE(parameterError({{"bilinear", "yes please"}}).find("expected true or false"), std::string::npos);
  EXPECT_NE(parameterError({{"visibility", "best"}}).find("expected one of: conservative, improved"), std::string::npos);
}

TEST(Parameters, OddOnlyIntegers) {
  std::vector<ParameterSpec> specs = {ParameterSpec::integer("kernel", 3, 1, 17, "kernel")};
  specs[0].oddOnly = true;
  EXPECT_EQ(resolveParameters("demo", specs, {{"kernel", "5"}}).getInt("kernel"), 5);
  EXPECT_THROW(resolveParameters("demo", specs, {{"kernel", "4"}}), InputError);
}

TEST(Parameters, SplitAssignment) {
  EXPECT_EQ(splitAssignment("a=b=c"), (std::pair<std::string, std::string>{"a", "b=c"}));
  EXPECT_EQ(splitAssignment("a="), (std::pair<std::string, std::string>{"a", ""}));
  EXPECT_THROW(splitAssignment("novalue"), InputError);
  EXPECT_THROW(splitAssignment("=1"), InputError);
}

TEST(Registry, EveryTechniqueDeclaresValidDefaults) {
  const auto techniques = registeredTechniques();
  ASSERT_FALSE(techniques.empty());
  for (const auto& t : techniques) {
    SCOPED_TRACE(t.info->id);
    EXPECT_FALSE(t.info->family.empty());
    EXPECT_FALSE(t.info->citation.empty());
    // Each default must itself pass validation when given explicitly.
    std::map<std::string, std::string> raw;
    for (const auto& spec : t.info->parameters) raw[spec.name] = formatValue(spec.defaultValue);
    EXPECT_NO_THROW(resolveParameters(t.info->id, t.info->parameters, raw));
  }
}

// The checks the plugin loader applies hold for every in-tree technique too.
TEST(Registry, EveryTechniquePassesTheSpecChecks) {
  for (const auto& t : registeredTechniques()) EXPECT_EQ(techniqueProblem(*t.info), "") << t.info->id;
}

TEST(Registry, SpecChecksNameWhatIsWrong) {
  TechniqueInfo info;
  info.id = "demo";
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': declares no pass (TechniqueInfo::passes)");
  info.passes = {{.name = "visibility", .paperStep = "the shadow test"}};
  EXPECT_EQ(techniqueProblem(info), "");
  info.parameters = {ParameterSpec::real("bias", 0.0, -1.0, 1.0, "a"), ParameterSpec::real("bias", 0.0, -1.0, 1.0, "b")};
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': parameter 'bias': declared twice");
  auto kernel = ParameterSpec::integer("kernel", 4, 1, 17, "even default");
  kernel.oddOnly = true;
  info.parameters = {kernel};
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': parameter 'kernel': odd_only needs an odd integer default");
  info.parameters = {ParameterSpec::real("bias", 2.0, -1.0, 1.0, "outside")};
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': parameter 'bias': default 2 is outside [-1, 1]");
  info.parameters = {ParameterSpec::choice("mode", "a", {}, "no choices")};
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': parameter 'mode': default 'a' is not among its choices");
  info.parameters = {ParameterSpec::boolean("two words", false, "not plain")};
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': parameter 'two words': name must be letters, digits and '_'");
  info.parameters = {};
  info.passes.push_back({.name = "visibility", .paperStep = "again"});
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': pass 'visibility' declared twice");
  info.passes = {{.name = "visibility", .paperStep = ""}};
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': pass 'visibility' names no paper step");
  info.passes = {{.name = "visibility", .paperStep = "the shadow test"}};
  info.resources = {{.name = "map", .formats = {GL_R32F}}, {.name = "map", .formats = {GL_R8}}};
  EXPECT_EQ(techniqueProblem(info), "technique 'demo': resource 'map' declared twice");
  info.resources = {};
  info.id = "a/b";
  EXPECT_EQ(techniqueProblem(info), "technique id 'a/b' must be letters, digits, '-' and '_'");
}

TEST(Registry, FindsSmAndSuggestsTheClosestIdsAndPluginForAnUnknownOne) {
  EXPECT_EQ(findTechnique("sm").info->id, "sm");
  // "pcss" is 2 edits from "pcf" (s→f, drop s), at least 3 from every other id.
  EXPECT_EQ(closestTechniqueIds("pcss", 1), std::vector<std::string>{"pcf"});
  EXPECT_EQ(closestTechniqueIds("smsr", 3).front(), "smsr");
  try {
    findTechnique("pcss");
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    const std::string what = error.what();
    EXPECT_EQ(what.rfind("--technique: unknown technique 'pcss' (closest: pcf, ", 0), 0u) << what;
    EXPECT_NE(what.find("needs --plugin PATH"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace testbed
