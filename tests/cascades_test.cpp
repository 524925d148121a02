// The shadow-map set-up as an axis of runs (docs/cascades.md), end to end: on the outdoor
// scene four PSSM cascades beat one map against the exact ground truth; a camera-only
// strafe leaves a stable fit's shadows still and moves a view fit's; records list every
// map; pcf runs on the same cascades as sm; bad combinations are bad input.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/harness/frame_runner.h"
#include "testbed/harness/record.h"
#include "testbed/metrics/metrics.h"
#include "tests/cli_helpers.h"
#include "tests/gl_fixture.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace testbed::test;

const fs::path kOutdoor = fs::path(TESTBED_SOURCE_DIR) / "scenes" / "outdoor";

ErrorMetrics smOnSunField(const ShadowSetup& setup) {
  sharedContext();
  const Scene scene = loadScene(kOutdoor / "sun_field.json");
  RenderSettings settings = renderSettings({640, 360}, 1024);
  settings.shadowSetup = setup;
  FrameRunner runner(scene, settings);
  return computeErrorMetrics(runTechnique(runner, "sm").visibility, groundTruthVisibility(runner));
}

// One 1024² map over the 400-unit field has texels of 0.56 units, and the slope offset
// lifts the near boxes' shadows off: leak (ground-truth shadow farther than 8 px from its
// boundary, shown lit) reads tens of %. Four PSSM cascades (λ = 0.5) give the nearest
// texels of 0.07 units. Asserted with a margin: at most a third of one map's mismatch and
// of its leak, which must itself be above 10 % so the comparison says something (measured
// on llvmpipe at 640×360: one map 0.79 % mismatch, 41.7 % leak; four cascades 0.075 %, 0 %).
TEST(Cascades, FourPssmCascadesBeatOneMapOnTheOutdoorScene) {
  const ErrorMetrics one = smOnSunField(parseShadowSetup(1, "pssm", ""));
  const ErrorMetrics four = smOnSunField(parseShadowSetup(4, "pssm", ""));
  std::cout << "sun-field sm 640x360 1024^2: one map mismatch " << one.mismatchPct << " % leak " << one.leakPct
            << " %; 4 pssm cascades mismatch " << four.mismatchPct << " % leak " << four.leakPct << " %\n";
  EXPECT_GT(one.leakPct, 10.0);
  EXPECT_LT(four.mismatchPct, one.mismatchPct / 3);
  EXPECT_LT(four.leakPct, one.leakPct / 3);
}

// pcf with one tap reads the receiver's cascade exactly as sm does: the shared lookup (two
// programs: bit for bit on llvmpipe, expectSameVisibilityAcrossPrograms's bounds elsewhere).
TEST(Cascades, PcfKernelOneIsSmOnCascades) {
  sharedContext();
  const Scene scene = loadScene(kOutdoor / "sun_field.json");
  for (const char* fit : {"view", "stable"}) {
    SCOPED_TRACE(fit);
    RenderSettings settings = renderSettings({320, 180}, 512);
    settings.shadowSetup = parseShadowSetup(3, "pssm", fit);
    FrameRunner runner(scene, settings);
    const ImageF sm = runTechnique(runner, "sm").visibility;
    const ImageF pcf = runTechnique(runner, "pcf", {{"kernel", "1"}}).visibility;
    expectSameVisibilityAcrossPrograms(sm, pcf, [&] { return groundTruthVisibility(runner); });
    EXPECT_GT(receiversOf(sm).fullyShadowed, 500);
  }
}

// --blend-band F: with F = 0 (the default) sm's cascaded output is binary, as it always
// was; with F = 0.5 the receivers in the last half of a slice before its split mix the two
// cascades' tests linearly, so those near a shadow's edge, where the two maps' texels
// disagree, take values strictly between 0 and 1 (sm's output is then filtered there),
// every value stays in [0, 1], and the receivers outside the bands keep their F = 0 answer:
// fewer than half of the receivers change. A stable fit's squares around each slice's
// sphere overlap the next slice's band, so the band is blended wherever it lies.
TEST(Cascades, BlendBandMixesTheCascadesNearASplit) {
  sharedContext();
  const Scene scene = loadScene(kOutdoor / "sun_field.json");
  auto sm = [&](double band) {
    RenderSettings settings = renderSettings({640, 360}, 256);
    settings.shadowSetup = parseShadowSetup(4, "pssm", "stable");
    settings.shadowSetup.blendBand = band;
    FrameRunner runner(scene, settings);
    return runTechnique(runner, "sm").visibility;
  };
  const ImageF off = sm(0), band = sm(0.5);
  auto between = [](const ImageF& image) {
    int count = 0;
    for (float v : image.pixels) count += v > 0.0f && v < 1.0f;
    return count;
  };
  EXPECT_EQ(between(off), 0) << "no band: binary";
  const int mixed = between(band);
  std::cout << "sun-field sm, 4 stable cascades, blend band 0.5: " << mixed << " receivers between 0 and 1, "
            << differingPixels(off, band) << " changed of " << receiversOf(off).count << "\n";
  EXPECT_GT(mixed, 20);
  for (float v : band.pixels)
    if (!std::isnan(v)) ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << v;
  EXPECT_LT(differingPixels(off, band), receiversOf(off).count / 2);
}

json readJson(const fs::path& file) { return json::parse(readFile(file)); }

// compare --frames all on the strafe: every technique's sequence record by id.
json strafe(const TempDir& tmp, const std::string& fit) {
  const fs::path out = tmp / fit;
  const RunResult run = runTestbed({"compare", "--scene", (kOutdoor / "sun_field_strafe.json").string(), "--techniques",
                                    "sm", "--cascades", "4", "--fit", fit, "--frames", "all", "--no-plot", "--size",
                                    "192x108", "--shadow-map", "512", "--out", out.string()});
  EXPECT_EQ(run.exitCode, 0) << run.describe();
  json byId = json::object();
  if (run.exitCode != 0) return byId;
  for (const json& record : readJson(out / "sequence.json")) byId[record.at("technique").get<std::string>()] = record;
  return byId;
}

// The camera translates sideways, its view direction fixed. Held view (docs/motion.md):
// frame t−1's maps, fitted to frame t−1's camera, seen through frame t's. A stable fit
// keeps every texel where it was: flicker and crawl exactly 0. A view fit crops each map to
// the moved slice, its texels move by fractions of a texel, and sm's jagged edges change.
TEST(Cascades, StrafeIsStillUnderTheStableFitAndNotUnderTheViewFit) {
  TempDir tmp;
  const json stable = strafe(tmp, "stable"), view = strafe(tmp, "view");
  ASSERT_TRUE(stable.contains("sm") && view.contains("sm"));
  const json &s = stable.at("sm").at("temporal"), &v = view.at("sm").at("temporal");
  std::cout << "strafe sm, 4 cascades: stable flicker " << s.at("flicker") << " crawl " << s.at("crawl_pct")
            << "; view flicker " << v.at("flicker") << " crawl " << v.at("crawl_pct") << "\n";
  EXPECT_EQ(s.at("held_renders").get<int>(), 5) << "the camera moved at every frame";
  EXPECT_GT(s.at("stable_pairs").get<double>(), 0.0);
  EXPECT_EQ(s.at("flicker").get<double>(), 0.0);
  EXPECT_EQ(s.at("crawl_pct").get<double>(), 0.0);
  EXPECT_GT(v.at("flicker").get<double>(), 0.0);
  EXPECT_GT(v.at("crawl_pct").get<double>(), 0.0);
}

// render --cascades 4: the record's light block lists the four maps, their splits
// contiguous from the first to the last, the nearest map's texels finer than the one map's;
// the block reads back as it was written.
TEST(Cascades, RecordListsEveryMap) {
  TempDir tmp;
  const RunResult run = runTestbed({"render", "--scene", (kOutdoor / "sun_field.json").string(), "--technique", "sm",
                                    "--cascades", "4", "--splits", "pssm:0.8", "--size", "96x54", "--shadow-map",
                                    "256", "--out", (tmp / "out").string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const json light = readJson(tmp / "out" / "sm.json").at("light");
  EXPECT_EQ(light.at("setup"), json({{"cascades", 4}, {"splits", "pssm:0.8"}, {"fit", "view"}, {"bias", "slope"}}));
  const json& maps = light.at("maps");
  ASSERT_EQ(maps.size(), 4u);
  for (std::size_t i = 0; i < maps.size(); ++i) {
    SCOPED_TRACE(i);
    const json& map = maps[i];
    EXPECT_LT(map.at("split")[0].get<double>(), map.at("split")[1].get<double>());
    if (i > 0) {
      EXPECT_EQ(map.at("split")[0], maps[i - 1].at("split")[1]);
    }
    EXPECT_EQ(map.at("near"), light.at("near")) << "each map keeps the light's depth range";
    EXPECT_GT(map.at("extent").get<double>(), 0.0);
  }
  EXPECT_LT(maps[0].at("texel_world")[0].get<double>(), light.at("texel_world")[0].get<double>() / 10);
  // Read back and written again, the block is the same.
  const LightRecord read = light.get<LightRecord>();
  EXPECT_EQ(read.maps.size(), 4u);
  EXPECT_EQ(json(read), light);
}

// Bad combinations: exit 2, one line naming the option (and the technique), nothing written.
TEST(Cascades, BadCombinationsAreBadInput) {
  TempDir tmp;
  const std::string field = (kOutdoor / "sun_field.json").string();
  const std::string fence = (fs::path(TESTBED_SOURCE_DIR) / "scenes" / "fence.json").string();
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "0"}, "--cascades: 0 is outside 1..4"},
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "9"}, "--cascades: 9 is outside 1..4"},
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "2", "--splits", "pssm:2"}, "--splits"},
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "2", "--splits", "sdsm"}, "--splits"},
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "2", "--fit", "tight"}, "--fit"},
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "2", "--fit", "scene"}, "--fit scene"},
      {{"render", "--scene", fence, "--technique", "sm", "--cascades", "2", "--fit", "stable"}, "spot light"},
      {{"render", "--scene", field, "--technique", "smsr", "--cascades", "2"}, "technique 'smsr' does not support"},
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "2", "--blend-band", "1.5"}, "--blend-band"},
      {{"render", "--scene", field, "--technique", "sm", "--cascades", "2", "--blend-band", "-0.1"}, "--blend-band"},
      {{"render", "--scene", field, "--technique", "sm", "--blend-band", "0.2"}, "--blend-band"},
      {{"compare", "--scene", field, "--techniques", "sm,vsm", "--cascades", "4"}, "technique 'vsm' does not support"}};
  for (const auto& [args, message] : cases) {
    const fs::path out = tmp / "bad";
    const RunResult run = runTestbed(with(args, {"--size", "64x36", "--out", out.string()}));
    SCOPED_TRACE(run.command);
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(message), std::string::npos) << run.err;
    EXPECT_FALSE(fs::exists(out) && !fs::is_empty(out)) << "nothing written";
  }
}

}  // namespace
}  // namespace testbed
