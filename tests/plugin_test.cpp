// Out-of-tree technique plugins (`--plugin PATH`, testbed/technique/plugin.h), end to end
// through the real binary as users load them. The fixtures are built from
// tests/plugin_example/: `example-sm` (a copy of sm with its own embedded shader) and one
// broken library per fault the loader must turn away with exit code 2.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/io/image_io.h"
#include "testbed/technique/plugin.h"
#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using namespace testbed::test;

const std::string kScene = std::string(TESTBED_SOURCE_DIR) + "/scenes/wall.json";
const std::vector<std::string> kPluginRunSize = {"--size", "160x90", "--shadow-map", "256"};

// ---------------------------------------------------------------------------------------
// A working plugin

TEST(Plugin, ListShowsThePluginsTechniqueBesideTheInTreeOnes) {
  const RunResult run = runTestbed({"list", "--json", "--plugin", TESTBED_PLUGIN_EXAMPLE});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const json all = json::parse(run.out);
  bool sm = false, example = false;
  for (const auto& t : all) {
    sm = sm || t["id"] == "sm";
    if (t["id"] == "example-sm") {
      example = true;
      EXPECT_EQ(t["family"], "plugin_example");
      EXPECT_EQ(t["parameters"].size(), 3u) << t.dump(2);
    }
  }
  EXPECT_TRUE(sm && example) << run.out;
  // Without --plugin it is not there.
  EXPECT_EQ(runTestbed({"list"}).out.find("example-sm"), std::string::npos);
}

// example-sm is sm's shader in a plugin: same visibility, pixel for pixel, and its own
// parameters accepted through --set like an in-tree technique's.
TEST(Plugin, RenderGivesSmsVisibility) {
  TempDir tmp;
  const RunResult sm =
      runTestbed(with({"render", "--scene", kScene, "--technique", "sm", "--out", (tmp / "sm").string()}, kPluginRunSize));
  ASSERT_EQ(sm.exitCode, 0) << sm.describe();
  const RunResult example =
      runTestbed(with({"render", "--plugin", TESTBED_PLUGIN_EXAMPLE, "--scene", kScene, "--technique", "example-sm",
                       "--set", "bias=0", "--out", (tmp / "example").string()},
                      kPluginRunSize));
  ASSERT_EQ(example.exitCode, 0) << example.describe();
  const json record = json::parse(readFile(tmp / "example" / "example-sm.json"));
  EXPECT_EQ(record["technique"], "example-sm");
  EXPECT_TRUE(record["gpu_ms"]["passes"].contains("visibility")) << record.dump(2);

  const testbed::ImageF a = testbed::readImage(tmp / "sm" / "sm.exr");
  const testbed::ImageF b = testbed::readImage(tmp / "example" / "example-sm.exr");
  ASSERT_EQ(a.pixels.size(), b.pixels.size());
  int differing = 0, shadowed = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const bool same = (std::isnan(a.pixels[i]) && std::isnan(b.pixels[i])) || a.pixels[i] == b.pixels[i];
    differing += !same;
    shadowed += a.pixels[i] < 0.5f;
  }
  EXPECT_EQ(differing, 0);
  EXPECT_GT(shadowed, 0) << "the scene should have shadows to compare";
}

TEST(Plugin, CompareRanksItBesideSm) {
  TempDir tmp;
  const RunResult run = runTestbed(with({"compare", "--plugin", TESTBED_PLUGIN_EXAMPLE, "--scene", kScene,
                                         "--techniques", "sm,example-sm", "--out", tmp.path().string()},
                                        kPluginRunSize));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const json all = json::parse(readFile(tmp / "metrics.json"));
  const json* sm = nullptr;
  const json* example = nullptr;
  for (const auto& record : all) {
    if (record["technique"] == "sm") sm = &record;
    if (record["technique"] == "example-sm") example = &record;
  }
  ASSERT_TRUE(sm && example) << all.dump(2);
  EXPECT_EQ((*example)["error"], (*sm)["error"]);
  EXPECT_NE(readFile(tmp / "report.md").find("example-sm"), std::string::npos);
  EXPECT_TRUE(fs::exists(tmp / "example-sm.exr"));
}

// ---------------------------------------------------------------------------------------
// The PCSS walk-through plugin (tests/plugin_example/pcss.cpp): a soft technique built only
// on the plugin API, the frame-aware setUniforms hook and testbed/glsl/light.glsl.

// The wall scene with its spot light's area radius replaced (0.5 → narrow penumbrae).
fs::path wallWithRadius(const TempDir& tmp, double radius) {
  json scene = json::parse(readFile(kScene));
  scene["light"]["radius"] = radius;
  return writeFile(tmp / ("wall_r" + std::to_string(radius) + ".json"), scene.dump());
}

const std::vector<std::string> kPcssSize = {"--size", "320x180", "--shadow-map", "512"};

// Renders pcss on `scene` and returns its visibility.
testbed::ImageF renderPcss(const TempDir& tmp, const fs::path& scene, const std::string& name) {
  const RunResult run = runTestbed(with({"render", "--plugin", TESTBED_PLUGIN_PCSS, "--scene", scene.string(),
                                         "--technique", "pcss", "--out", (tmp / name).string()},
                                        kPcssSize));
  EXPECT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_EQ(run.err.find("warning"), std::string::npos) << run.err;
  return testbed::readImage(tmp / name / "pcss.exr");
}

struct VisibilityCounts {
  int receivers = 0, outOfRange = 0, penumbra = 0, shadowed = 0;
};

// Receivers are the non-NaN pixels; penumbra: strictly between 2 % and 98 % lit.
VisibilityCounts countVisibility(const testbed::ImageF& v) {
  VisibilityCounts c;
  for (float x : v.pixels) {
    if (std::isnan(x)) continue;
    ++c.receivers;
    c.outOfRange += !(std::isfinite(x) && x >= 0.0f && x <= 1.0f);
    c.penumbra += x > 0.02f && x < 0.98f;
    c.shadowed += x < 0.5f;
  }
  return c;
}

TEST(PcssPlugin, LoadsAndRendersFiniteVisibilityInZeroOne) {
  const RunResult list = runTestbed({"list", "--json", "--plugin", TESTBED_PLUGIN_PCSS});
  ASSERT_EQ(list.exitCode, 0) << list.describe();
  bool found = false;
  for (const auto& t : json::parse(list.out))
    if (t["id"] == "pcss") {
      found = true;
      EXPECT_EQ(t["family"], "plugin_example");
      EXPECT_EQ(t["output"], "filtered") << t.dump(2);
    }
  EXPECT_TRUE(found) << list.out;
  TempDir tmp;
  const VisibilityCounts c = countVisibility(renderPcss(tmp, kScene, "pcss"));
  EXPECT_GT(c.receivers, 0);
  EXPECT_EQ(c.outOfRange, 0);
  EXPECT_GT(c.shadowed, 0) << "the wall's shadow";
  EXPECT_GT(c.penumbra, 0) << "a radius-2 light gives penumbrae";
}

// Fernando's estimate: the penumbra scales with the light's size, so a light 6× wider
// gives clearly more partly lit pixels on the same scene.
// Forgetting --plugin: the closest in-tree ids and the option are suggested, on one line.
TEST(PcssPlugin, WithoutPluginTheUnknownIdSuggestsTheClosestAndPlugin) {
  TempDir tmp;
  const RunResult run = runTestbed(with({"render", "--scene", kScene, "--technique", "pcss", "--out",
                                         (tmp / "out").string()},
                                        kPluginRunSize));
  EXPECT_EQ(run.exitCode, 2) << run.describe();
  EXPECT_NE(run.err.find("unknown technique 'pcss' (closest: pcf, "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--plugin PATH"), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.err;
}

TEST(PcssPlugin, PenumbraWidensWithTheLightRadius) {
  TempDir tmp;
  const VisibilityCounts narrow = countVisibility(renderPcss(tmp, wallWithRadius(tmp, 0.5), "narrow"));
  const VisibilityCounts wide = countVisibility(renderPcss(tmp, wallWithRadius(tmp, 3.0), "wide"));
  std::cout << "pcss penumbra pixels on wall (320x180, 512²): radius 0.5: " << narrow.penumbra
            << ", radius 3: " << wide.penumbra << "\n";
  EXPECT_EQ(narrow.outOfRange + wide.outOfRange, 0);
  EXPECT_GT(narrow.penumbra, 0);
  EXPECT_GT(wide.penumbra, 2 * narrow.penumbra);
}

// Against the area-light reference (compare --area-samples; the wall's light has radius 2)
// PCSS's penumbrae score a lower soft RMSE than sm's hard edges.
TEST(PcssPlugin, ScoresALowerSoftErrorThanSmAgainstTheAreaLightReference) {
  TempDir tmp;
  const RunResult run = runTestbed(with({"compare", "--plugin", TESTBED_PLUGIN_PCSS, "--scene", kScene,
                                         "--techniques", "sm,pcss", "--area-samples", "32", "--out",
                                         tmp.path().string()},
                                        kPcssSize));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  std::map<std::string, double> soft;
  for (const auto& record : json::parse(readFile(tmp / "metrics.json")))
    if (record.contains("error") && record["error"].is_object() && record["error"]["soft_rmse"].is_number())
      soft[record["technique"]] = record["error"]["soft_rmse"].get<double>();
  ASSERT_TRUE(soft.count("sm") && soft.count("pcss")) << readFile(tmp / "metrics.json");
  std::cout << "soft_rmse on wall (320x180, 512², 32 area samples): sm " << soft["sm"] << ", pcss " << soft["pcss"]
            << "\n";
  EXPECT_LT(soft["pcss"], soft["sm"]);
}

// ---------------------------------------------------------------------------------------
// The cascaded plugin (tests/plugin_example/pssm.cpp): a technique with its own passes and
// several maps, built only on the plugin API (docs/writing-a-technique.md "A technique with
// its own passes").

// A grazing outdoor scene: a 400×400 ground seen from 5 units up, a low sun, casters 8 to
// 300 units ahead; one map fitted to the whole ground has texels of half a unit.
fs::path outdoorScene(const TempDir& tmp) {
  const json scene = {
      {"name", "outdoor-grazing"},
      {"camera", {{"eye", {0, 5, -190}}, {"target", {0, 3, -150}}, {"fov_y", 50}, {"near", 0.5}, {"far", 500}}},
      {"light", {{"type", "directional"}, {"direction", {0.35, -0.45, 1}}, {"target", {0, 0, 0}}}},
      {"objects",
       {{{"primitive", "plane"}, {"size", {400, 400}}},
        {{"primitive", "box"}, {"size", {2, 2, 2}}, {"translate", {1, 1, -182}}},
        {{"primitive", "box"}, {"size", {4, 4, 4}}, {"translate", {-4, 2, -160}}},
        {{"primitive", "box"}, {"size", {10, 10, 10}}, {"translate", {8, 5, -90}}},
        {{"primitive", "box"}, {"size", {30, 30, 30}}, {"translate", {-20, 15, 110}}}}}};
  return writeFile(tmp / "outdoor.json", scene.dump());
}

const std::vector<std::string> kPssmSize = {"--size", "320x180", "--shadow-map", "512"};

// Each cascade is timed as its own pass, and the record's light block lists every map: its
// split of the camera's depths (contiguous, in order) and its texel, finer than the one
// fitted map's. A technique reporting no maps (sm) keeps the light block it always had.
TEST(PssmPlugin, RecordListsEveryCascadeWithItsSplitAndTexel) {
  TempDir tmp;
  const fs::path scene = outdoorScene(tmp);
  const RunResult run = runTestbed(with({"render", "--plugin", TESTBED_PLUGIN_PSSM, "--scene", scene.string(),
                                         "--technique", "pssm", "--set", "cascades=2", "--out", (tmp / "pssm").string()},
                                        kPssmSize));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const json record = json::parse(readFile(tmp / "pssm" / "pssm.json"));
  const json& passes = record["gpu_ms"]["passes"];
  EXPECT_TRUE(passes.contains("cascade-0") && passes.contains("cascade-1") && !passes.contains("cascade-2"))
      << passes.dump();
  const json& light = record["light"];
  ASSERT_EQ(light["maps"].size(), 2u) << light.dump(2);
  const double texel = light["texel_world"][0].get<double>();
  double previous = -1;
  for (const json& map : light["maps"]) {
    const double begin = map["split"][0].get<double>(), end = map["split"][1].get<double>();
    if (previous >= 0) EXPECT_DOUBLE_EQ(begin, previous) << "contiguous splits";
    EXPECT_LT(begin, end);
    previous = end;
    EXPECT_LT(map["texel_world"][0].get<double>(), texel) << map.dump();
    EXPECT_EQ(map["type"], "directional");
    EXPECT_TRUE(map.contains("extent") && map.contains("depth_step_world") && map.contains("offset_world")) << map.dump();
  }
  EXPECT_DOUBLE_EQ(light["maps"][0]["split"][0].get<double>(), 0.5) << "the first split starts at the camera's near plane";

  const RunResult sm = runTestbed(
      with({"render", "--scene", scene.string(), "--technique", "sm", "--out", (tmp / "sm").string()}, kPssmSize));
  ASSERT_EQ(sm.exitCode, 0) << sm.describe();
  const json smLight = json::parse(readFile(tmp / "sm" / "sm.json"))["light"];
  EXPECT_FALSE(smLight.contains("maps") || smLight.contains("split")) << smLight.dump(2);
}

// Four splits of the grazing view against sm's one fitted map: fewer pixels disagree with
// the exact shadows (measured 0.196 % → 0.073 % at 320×180, 512² maps), none leaks more.
TEST(PssmPlugin, ReducesSmsMismatchOnAGrazingOutdoorScene) {
  TempDir tmp;
  const RunResult run = runTestbed(with({"compare", "--plugin", TESTBED_PLUGIN_PSSM, "--scene",
                                         outdoorScene(tmp).string(), "--techniques", "sm,pssm", "--out",
                                         (tmp / "out").string()},
                                        kPssmSize));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  std::map<std::string, json> error;
  for (const auto& record : json::parse(readFile(tmp / "out" / "metrics.json"))) error[record["technique"]] = record["error"];
  ASSERT_TRUE(error.count("sm") && error.count("pssm")) << run.out;
  const double sm = error["sm"]["mismatch_pct"].get<double>(), pssm = error["pssm"]["mismatch_pct"].get<double>();
  std::cout << "mismatch on the grazing outdoor scene (320x180, 512² maps): sm " << sm << " %, pssm " << pssm << " %\n";
  EXPECT_LT(pssm, 0.6 * sm);
  EXPECT_LE(error["pssm"]["leak_pct"].get<double>(), error["sm"]["leak_pct"].get<double>());
}

// ---------------------------------------------------------------------------------------
// Bad plugins: exit 2, one line naming the path (and the id), no output written.

// `render` is the command that would write files; the loading path is the same for all.
void expectRejected(const std::string& plugin, const std::string& expected,
                    const std::vector<std::string>& command = {"render", "--technique", "sm"}) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  std::vector<std::string> args = with(command, {"--plugin", plugin});
  if (command[0] != "list") args = with(args, with({"--scene", kScene, "--out", out.string()}, kPluginRunSize));
  const RunResult run = runTestbed(args);
  EXPECT_EQ(run.exitCode, 2) << run.describe();
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_EQ(run.err.rfind("testbed: --plugin " + plugin + ": ", 0), 0u) << run.err;
  EXPECT_NE(run.err.find(expected), std::string::npos) << run.err;
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << "one line: " << run.err;
  EXPECT_FALSE(fs::exists(out)) << "nothing written by " << run.command;
}

// Every command that takes --plugin loads it before doing anything else.
TEST(Plugin, MissingFileIsRejectedByEveryCommand) {
  TempDir tmp;
  const std::string missing = (tmp / "nowhere.so").string();
  const std::vector<std::vector<std::string>> commands = {
      {"list"}, {"render", "--technique", "sm"}, {"compare", "--techniques", "sm"}, {"groundtruth"}};
  for (const auto& command : commands) {
    SCOPED_TRACE(command[0]);
    expectRejected(missing, "no such file", command);
  }
}

TEST(Plugin, FileThatIsNotASharedLibraryIsRejected) {
  TempDir tmp;
  const fs::path fake = tmp / "fake.so";
  std::ofstream(fake) << "not an ELF file\n";
  expectRejected(fake.string(), "cannot load it as a shared library");
}

TEST(Plugin, LibraryWithoutRegistrationFunctionIsRejected) {
  expectRejected(TESTBED_PLUGIN_BAD_NO_ENTRY, "exports no testbed_register_plugin");
}

// Entry names exported as data symbols: refused from the ELF symbol table, never called.
TEST(Plugin, EntryPointsThatAreDataNotFunctionsAreRejected) {
  expectRejected(TESTBED_PLUGIN_BAD_DATA_ENTRY, "testbed_plugin_api_version is not a function");
}

TEST(Plugin, IdOfAnInTreeTechniqueIsRejected) {
  expectRejected(TESTBED_PLUGIN_BAD_DUPLICATE_ID, "technique 'sm': the id is already registered");
}

// The same id from two libraries (a copy of the example under another name).
TEST(Plugin, IdRegisteredByAnEarlierPluginIsRejected) {
  TempDir tmp;
  const fs::path copy = tmp / "copy.so";
  fs::copy_file(TESTBED_PLUGIN_EXAMPLE, copy);
  const RunResult run = runTestbed({"list", "--plugin", TESTBED_PLUGIN_EXAMPLE, "--plugin", copy.string()});
  EXPECT_EQ(run.exitCode, 2) << run.describe();
  EXPECT_EQ(run.err, "testbed: --plugin " + copy.string() + ": technique 'example-sm': the id is already registered\n");
  // The same file twice loads once.
  const RunResult twice = runTestbed({"list", "--plugin", TESTBED_PLUGIN_EXAMPLE, "--plugin", TESTBED_PLUGIN_EXAMPLE});
  EXPECT_EQ(twice.exitCode, 0) << twice.describe();
}

TEST(Plugin, InvalidParameterSpecIsRejected) {
  expectRejected(TESTBED_PLUGIN_BAD_PARAMETER_SPEC,
                 "technique 'bad-plugin': parameter 'kernel': default 4 is outside [1, 3]");
}

TEST(Plugin, ShaderUnderATakenNameWithOtherTextIsRejected) {
  expectRejected(TESTBED_PLUGIN_BAD_SHADER_CLASH,
                 "shader 'techniques/shadow_map/shadow_map_visibility.frag' is already embedded with other text");
}

TEST(Plugin, OtherApiVersionIsRejected) {
  // bad_plugin.cpp reports TESTBED_PLUGIN_API_VERSION + 100.
  expectRejected(TESTBED_PLUGIN_BAD_API_VERSION,
                 "built for plugin API version " + std::to_string(TESTBED_PLUGIN_API_VERSION + 100) +
                     ", this testbed loads version " + std::to_string(TESTBED_PLUGIN_API_VERSION));
}

}  // namespace
