// The light set-up's hard cases: the shared shadow map must not be what the error columns
// measure. Scenes written with careless or extreme light values — spot near 0.01…10 and far
// up to 1e5, directional lights 2°–10° above the floor with extents smaller than the
// receivers — at 16, 24 and 32f depth, with a CGAL mesh (the dragon) as well as boxes,
// 640×360 screen and 512² map, all with the default (fitted) light set-up:
// - sm: leak_pct ≤ 0.05 and overestimation_pct ≤ 0.05 everywhere (one exception at 32f,
//   see the cases), boundary_px.mean ≤ 1 px
//   where the light is at least 10° above the receiver (below, projection aliasing is the
//   technique's business: printed, not asserted);
// - every registered technique (16-bit, where the polygon offset is coarsest): leak_pct
//   ≤ sm's + 0.02; but esm and vsm, whose light bleeding where a receiver lies close
//   behind its occluder (the dragon's own folds: 0.40 % and 0.08 % here, 0 on the boxes)
//   is their filter's, not the set-up's: printed, and held to ≤ sm's + 0.5.
// Each case loads its scene once and shares the G-buffer's ground truth across formats.
#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "testbed/harness/frame_runner.h"
#include "testbed/metrics/metrics.h"
#include "tests/gl_fixture.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

using nlohmann::json;

struct HardCase {
  const char* name;
  json light;
  bool mesh;               // the dragon on the floor (else boxes)
  bool steep;              // light ≥ 10° above the receivers: boundary_px.mean asserted
  double overestimation32f = 0.05;  // sm's bound at 32f (see the dragon under a 10° sun)
  bool everyTechnique = true;    // false where the fitted set-up equals another case's
};

void PrintTo(const HardCase& c, std::ostream* out) { *out << c.name; }

json spotLight(double nearPlane, double farPlane) {
  // The papers' spot light (fov 45) about 150 units from the scene's centre.
  return {{"type", "spot"}, {"eye", {40, 110, 100}}, {"target", {0, 0, 0}}, {"fov", 45},
          {"near", nearPlane}, {"far", farPlane}};
}

json sun(double elevationDegrees, double extent) {
  const double e = elevationDegrees * 3.14159265358979 / 180;
  json light = {{"type", "directional"}, {"direction", {std::cos(e), -std::sin(e), 0.35 * std::cos(e)}}};
  if (extent > 0) light["extent"] = extent;
  return light;
}

// A floor, a wall between it and the light, and a blocker (the dragon, or a box) in front.
Scene hardScene(const HardCase& c) {
  json objects = json::array({
      {{"primitive", "plane"}, {"size", {90, 90}}},
      {{"primitive", "box"}, {"size", {30, 14, 1.5}}, {"rotate", {0, 70, 0}}, {"translate", {-18, 7, 14}}},
  });
  if (c.mesh)
    objects.push_back({{"mesh", "dragon"}, {"fit", 24}, {"translate", {6, 6.5, -4}}});
  else
    objects.push_back({{"primitive", "box"}, {"size", {8, 4, 8}}, {"rotate", {0, 25, 0}}, {"translate", {8, 9, -6}}});
  const json scene = {
      {"name", c.name},
      {"camera", {{"eye", {-10, 55, -75}}, {"target", {0, 0, 0}}, {"near", 1}, {"far", 500}}},
      {"light", c.light},
      {"objects", objects},
  };
  return parseScene(scene, std::string(TESTBED_SOURCE_DIR) + "/tests/" + c.name + ".json");
}

class LightSetupHardCases : public ::testing::TestWithParam<HardCase> {
 protected:
  void SetUp() override { test::sharedContext(); }
};

void print(const std::string& scene, const std::string& format, const std::string& id, const ErrorMetrics& m) {
  char line[200];
  std::snprintf(line, sizeof line, "[ light    ] %-24s %-3s %-16s leak %.3f%%  over %.3f%%  bnd %.3f px  mismatch %.3f%%\n",
                scene.c_str(), format.c_str(), id.c_str(), m.leakPct, m.overestimationPct, m.boundaryMean, m.mismatchPct);
  std::cout << line << std::flush;
}

TEST_P(LightSetupHardCases, ShadowMapSetUpDoesNotLeak) {
  const HardCase& c = GetParam();
  const Scene scene = hardScene(c);
  ImageF truth;
  for (const DepthFormat format : {DepthFormat::D16, DepthFormat::D24, DepthFormat::D32F}) {
    const std::string formatName = depthFormatName(format);
    SCOPED_TRACE(std::string(c.name) + " " + formatName);
    RenderSettings settings;
    settings.size = {640, 360};
    settings.shadowMapSize = 512;
    settings.depthFormat = format;
    FrameRunner runner(scene, settings);
    ASSERT_TRUE(runner.light().fitted);
    if (truth.pixels.empty()) truth = test::groundTruthVisibility(runner);
    const ErrorMetrics sm = computeErrorMetrics(test::runTechnique(runner, "sm").visibility, truth);
    print(c.name, formatName, "sm", sm);
    ASSERT_GT(sm.gtBoundaryPixels, 500);  // there is a shadow to get right
    EXPECT_LE(sm.leakPct, 0.05);
    EXPECT_LE(sm.overestimationPct, format == DepthFormat::D32F ? c.overestimation32f : 0.05);
    if (c.steep) EXPECT_LE(sm.boundaryMean, 1.0);
    if (format != DepthFormat::D16 || !c.everyTechnique) continue;
    for (const auto& technique : registeredTechniques()) {
      const std::string id = technique.info->id;
      if (id == "sm") continue;
      const ErrorMetrics m = computeErrorMetrics(test::runTechnique(runner, id).visibility, truth);
      print(c.name, formatName, id, m);
      const bool bleeds = id == "esm" || id == "vsm";
      EXPECT_LE(m.leakPct, sm.leakPct + (bleeds ? 0.5 : 0.02)) << id;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Grid, LightSetupHardCases,
    ::testing::Values(HardCase{"spot-papers-dragon", spotLight(1, 1000), true, true},
                      HardCase{"spot-careless-boxes", spotLight(0.01, 1e5), false, true},
                      // Fitted, near 10 / far 1e5 renders what near 1 / far 1000 does: sm only.
                      HardCase{"spot-near10-dragon", spotLight(10, 1e5), true, true, 0.05, false},
                      HardCase{"sun-10deg-small-extent", sun(10, 30), false, true},
                      HardCase{"sun-2deg-small-extent", sun(2, 30), false, false},
                      // The one exception. Before offset_units counted 16-bit steps at every
                      // format, 24 and 32f left the dragon's terminator self-shadowed here
                      // (0.058 %); now 24 bits gives 16's 0.048 %, and 32f, the same offset
                      // but no rounding of the stored depth, 0.053 %.
                      HardCase{"sun-10deg-fitted-dragon", sun(10, 0), true, true, 0.055}),
    [](const auto& info) { return test::caseName(info.param.name); });

}  // namespace
}  // namespace testbed
