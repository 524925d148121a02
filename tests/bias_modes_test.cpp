// The shadow-map set-up's bias modes (--bias, docs/cascades.md "Bias modes"), end to end:
// the default is the slope-scaled polygon offset, unchanged; on a lit floor under a low sun,
// where sm without the offset's slope term shows acne, the normal offset (Holbert, GDC 2011)
// and the receiver-plane depth bias (Isidoro, GDC 2006) show none, on one map and on
// cascades; records name the mode; bad words are bad input. The helpers' math on a known
// plane is pinned in testbed/render/light_glsl_test.cpp (BiasGlsl).
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/harness/frame_runner.h"
#include "testbed/io/image_io.h"
#include "testbed/scene/scene.h"
#include "tests/cli_helpers.h"
#include "tests/gl_fixture.h"
#include "tests/test_scenes.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace testbed::test;

const fs::path kSunField = fs::path(TESTBED_SOURCE_DIR) / "scenes" / "outdoor" / "sun_field.json";

// Shadowed (below 0.5) receivers of `technique` on the floor under `setup`.
int acnePixels(const ShadowSetup& setup, const std::string& technique, const std::map<std::string, std::string>& set) {
  sharedContext();
  RenderSettings settings = renderSettings({160, 90}, 256);
  settings.shadowSetup = setup;
  const Scene scene = floorUnderSun(10);  // every receiver lit in the ground truth: a shadowed one is acne
  FrameRunner runner(scene, settings);
  const Receivers truth = receiversOf(groundTruthVisibility(runner));
  EXPECT_GT(truth.count, 5000);
  EXPECT_EQ(truth.dark, 0) << "the floor is lit";
  return receiversOf(runTechnique(runner, technique, set).visibility).dark;
}

// Without the polygon offset's slope term (offset_factor 0; its constant 20 steps kept) the
// floor at 80° from the light shadows itself in bands: more than a tenth of its pixels. The
// normal offset (k = 1 texel) and the receiver-plane bias (c = 2 steps) clear every pixel,
// on one map and on four cascades, for sm and for pcf's 3×3 kernel (the receiver plane
// follows each tap; the normal offset needs k ≥ 1 + the kernel's reach, so pcf takes k = 2.5).
TEST(BiasModes, NormalOffsetAndReceiverPlaneRemoveAcneOnALowSunFloor) {
  const std::map<std::string, std::string> noSlope{{"offset_factor", "0"}};
  for (int cascades : {1, 4}) {
    SCOPED_TRACE(cascades);
    const int slope = acnePixels(parseShadowSetup(cascades, "pssm", "", "slope"), "sm", noSlope);
    std::cout << cascades << " map(s): slope offset 0 leaves " << slope << " acne pixels\n";
    EXPECT_GT(slope, 1000);
    EXPECT_EQ(acnePixels(parseShadowSetup(cascades, "pssm", "", "normal"), "sm", noSlope), 0);
    EXPECT_EQ(acnePixels(parseShadowSetup(cascades, "pssm", "", "receiver-plane"), "sm", noSlope), 0);
    EXPECT_EQ(acnePixels(parseShadowSetup(cascades, "pssm", "", "receiver-plane"), "pcf", noSlope), 0);
    EXPECT_EQ(acnePixels(parseShadowSetup(cascades, "pssm", "", "normal:2.5"), "pcf", noSlope), 0);
  }
}

json readJson(const fs::path& file) { return json::parse(readFile(file)); }

RunResult renderSunField(const fs::path& out, const std::vector<std::string>& more) {
  return runTestbed(with({"render", "--scene", kSunField.string(), "--technique", "sm", "--size", "96x54",
                          "--shadow-map", "256", "--out", out.string()},
                         more));
}

// --bias slope is the default: the same pixels, bit for bit, and a record without a set-up
// block, as before the bias modes existed.
TEST(BiasModes, SlopeIsTheDefaultBitForBit) {
  EXPECT_TRUE(parseShadowSetup(1, "pssm", "").isDefault());
  TempDir tmp;
  ASSERT_EQ(renderSunField(tmp / "default", {}).exitCode, 0);
  ASSERT_EQ(renderSunField(tmp / "slope", {"--bias", "slope"}).exitCode, 0);
  EXPECT_EQ(differingPixels(readImage(tmp / "default" / "sm.exr"), readImage(tmp / "slope" / "sm.exr")), 0);
  EXPECT_FALSE(readJson(tmp / "slope" / "sm.json").at("light").contains("setup"));
}

// The record's set-up block names the mode; the offset it states is what the mode applies of
// the technique's polygon offset (the normal offset keeps only the constant term).
TEST(BiasModes, RecordNamesTheModeAndTheAppliedOffset) {
  TempDir tmp;
  const RunResult slope = renderSunField(tmp / "slope", {"--set", "offset_units=20"});
  const RunResult normal = renderSunField(tmp / "normal", {"--bias", "normal:1.5", "--set", "offset_factor=0"});
  ASSERT_EQ(slope.exitCode, 0) << slope.describe();
  ASSERT_EQ(normal.exitCode, 0) << normal.describe();
  const json light = readJson(tmp / "normal" / "sm.json").at("light");
  EXPECT_EQ(light.at("setup"), json({{"cascades", 1}, {"splits", "pssm:0.5"}, {"fit", "scene"}, {"bias", "normal:1.5"}}));
  // offset_factor 0 under the slope bias states the same offset as the normal offset's.
  const RunResult slopeNoFactor = renderSunField(tmp / "nofactor", {"--set", "offset_factor=0"});
  ASSERT_EQ(slopeNoFactor.exitCode, 0);
  EXPECT_EQ(light.at("offset_world"), readJson(tmp / "nofactor" / "sm.json").at("light").at("offset_world"));
  const RunResult plane = renderSunField(tmp / "plane", {"--bias", "receiver-plane", "--cascades", "2"});
  ASSERT_EQ(plane.exitCode, 0) << plane.describe();
  const json planeLight = readJson(tmp / "plane" / "sm.json").at("light");
  EXPECT_EQ(planeLight.at("setup").at("bias"), "receiver-plane:2");
  EXPECT_EQ(planeLight.at("offset_world"), json({0.0, 0.0})) << "no polygon offset";
}

// Bad words: exit 2, one line naming --bias (and the technique that takes no bias modes).
TEST(BiasModes, BadInputIsExitTwo) {
  TempDir tmp;
  const std::vector<std::pair<std::string, std::string>> cases{
      {"tilt", "--bias: expected slope, normal[:k] or receiver-plane[:c]"},
      {"slope:1", "--bias: expected slope"},
      {"normal:-1", "--bias: expected normal:k with k in [0, 16]"},
      {"normal:17", "--bias: expected normal:k"},
      {"normal:", "--bias: expected normal:k"},
      {"receiver-plane:x", "--bias: expected receiver-plane:c"},
      {"receiver-plane:1e9", "--bias: expected receiver-plane:c"}};
  for (const auto& [word, message] : cases) {
    const RunResult run = renderSunField(tmp / "bad", {"--bias", word});
    SCOPED_TRACE(run.command);
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
  }
  const RunResult smsr = runTestbed({"render", "--scene", kSunField.string(), "--technique", "smsr", "--bias",
                                     "normal", "--size", "64x36", "--out", (tmp / "smsr").string()});
  EXPECT_TRUE(rejectedWithOneLine(smsr));
  EXPECT_NE(smsr.err.find("--bias normal:1: technique 'smsr' does not take"), std::string::npos) << smsr.err;
}

}  // namespace
}  // namespace testbed
