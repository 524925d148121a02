// End-to-end tests of the `testbed` command line (README "Command line"; docs/record.md
// "The record"; docs/scenes.md "Scenes"). They run the real binary as a subprocess, the
// way users and scripts do, so they catch what unit tests cannot: option parsing, exit
// codes, the one-line error contract, and which files end up in --out.
//
// Every test works in its own temporary directory, so tests can run in parallel (ctest
// runs each discovered test as its own process) and leave nothing behind.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/io/image_io.h"
#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace testbed::test;

// `render --scene S` plus defaults (technique sm, a small size) for every option that
// `extra` does not set itself, then `extra`.
std::vector<std::string> renderArgs(const fs::path& scene, const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"render", "--scene", scene.string()};
  const std::vector<std::pair<std::string, std::string>> defaults = {
      {"--technique", "sm"}, {"--size", "160x90"}, {"--shadow-map", "256"}};  // well under a second
  for (const auto& [flag, value] : defaults) {
    if (std::find(extra.begin(), extra.end(), flag) == extra.end()) {
      args.push_back(flag);
      args.push_back(value);
    }
  }
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

fs::path bundledScene(const std::string& name) { return fs::path(TESTBED_SOURCE_DIR) / "scenes" / name; }

// A valid scene (the camera and light of scenes/wall.json) around the given objects.
std::string sceneWithObjects(const std::string& objects) {
  return R"({
  "name": "cli-test",
  "camera": {"eye": [0, 30, -45], "target": [0, 0, 5], "fov_y": 45, "near": 1, "far": 500},
  "light": {"type": "spot", "eye": [0, 60, 60], "target": [0, 0, 0], "fov": 60, "near": 1, "far": 300},
  "objects": [)" + objects + R"(]
}
)";
}

// A closed unit cube as OFF: 8 vertices, 6 quads (OpenMesh triangulates them).
const char* const kCubeOff = R"(OFF
8 6 0
-0.5 -0.5 -0.5
 0.5 -0.5 -0.5
 0.5  0.5 -0.5
-0.5  0.5 -0.5
-0.5 -0.5  0.5
 0.5 -0.5  0.5
 0.5  0.5  0.5
-0.5  0.5  0.5
4 0 3 2 1
4 4 5 6 7
4 0 1 5 4
4 2 3 7 6
4 1 2 6 5
4 0 4 7 3
)";

bool sameFloat(float a, float b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

// Checks the files a successful `render` of technique `id` leaves: exactly the three
// outputs, no staging leftovers; returns the parsed record.
json expectRenderOutputs(const fs::path& out, const std::string& id) {
  EXPECT_EQ(filesIn(out), (std::vector<std::string>{id + ".exr", id + ".json", id + ".png"}));
  try {
    return json::parse(readFile(out / (id + ".json")));
  } catch (const std::exception& e) {
    ADD_FAILURE() << out / (id + ".json") << " is not valid JSON: " << e.what();
    return json();
  }
}

// ---------------------------------------------------------------------------------------
// Good runs

TEST(CliRender, BundledSceneWritesExactlyTheThreeOutputsAndARecord) {
  TempDir tmp;
  const fs::path out = tmp / "nested" / "out";  // --out folders are created as needed
  const RunResult run = runTestbed(renderArgs(bundledScene("wall.json"), {"--out", out.string()}));
  ASSERT_EQ(run.exitCode, 0) << run.describe();

  const json record = expectRenderOutputs(out, "sm");
  ASSERT_TRUE(record.is_object());
  // The record's fields (docs/record.md).
  EXPECT_EQ(record.value("technique", ""), "sm");
  EXPECT_EQ(record.value("scene", ""), "wall");  // the scene's "name"
  EXPECT_EQ(record.value("size", json()), json::array({160, 90}));
  EXPECT_EQ(record.value("shadow_map", 0), 256);
  EXPECT_EQ(record.value("depth_format", ""), "16");  // the default
  ASSERT_TRUE(record.contains("params") && record["params"].is_object()) << record.dump(2);
  EXPECT_TRUE(record["params"].contains("bias")) << "every declared parameter is recorded, defaults included";
  ASSERT_TRUE(record.contains("gpu_ms") && record["gpu_ms"].is_object()) << record.dump(2);
  ASSERT_TRUE(record["gpu_ms"]["total"].is_number()) << record.dump(2);
  EXPECT_GT(record["gpu_ms"]["total"].get<double>(), 0.0);
  ASSERT_TRUE(record["gpu_ms"]["passes"].is_object()) << record.dump(2);
  EXPECT_FALSE(record["gpu_ms"]["passes"].empty());
  for (const auto& [pass, ms] : record["gpu_ms"]["passes"].items()) {
    EXPECT_TRUE(ms.is_number() && ms.get<double>() >= 0.0) << "pass " << pass << ": " << ms;
  }
  ASSERT_TRUE(record["memory_bytes"].is_number_unsigned()) << record.dump(2);
  EXPECT_GT(record["memory_bytes"].get<std::uint64_t>(), 0u);
  ASSERT_TRUE(record["backend"].is_string()) << record.dump(2);
  EXPECT_EQ(record["backend"].get<std::string>().rfind("osmesa", 0), 0u) << record["backend"];
  EXPECT_TRUE(record.contains("error")) << "null until compared with ground truth";

  // The images: a shaded PNG and a one-channel visibility EXR at the screen size. The wall
  // scene has both lit and shadowed receivers and background (NaN) pixels.
  const testbed::ImageF png = testbed::readImage(out / "sm.png");
  EXPECT_EQ(png.width, 160);
  EXPECT_EQ(png.height, 90);
  const testbed::ImageF exr = testbed::readImage(out / "sm.exr");
  ASSERT_EQ(exr.width, 160);
  ASSERT_EQ(exr.height, 90);
  ASSERT_EQ(exr.channels, 1);
  int lit = 0, shadowed = 0, background = 0;
  for (float v : exr.pixels) {
    if (std::isnan(v)) ++background;
    else if (v >= 0.5f) ++lit;
    else ++shadowed;
  }
  EXPECT_GT(lit, 0);
  EXPECT_GT(shadowed, 0);
  EXPECT_GT(background, 0);
}

// memory_bytes is counted from the textures the technique owns: for sm that is the shadow
// map alone, so it follows the --shadow-map size and the depth format's texel size.
TEST(CliRender, MemoryBytesFollowShadowMapSizeAndDepthFormat) {
  struct Case {
    std::string depthFormat;
    std::uint64_t bytes;
  };
  const std::uint64_t texels = 1024 * 1024;
  for (const Case& c : {Case{"16", texels * 2}, Case{"32f", texels * 2 * 2}, Case{"24", texels * 4}}) {
    SCOPED_TRACE("--depth-format " + c.depthFormat);
    TempDir tmp;
    const RunResult run = runTestbed(renderArgs(bundledScene("wall.json"),
                                                {"--shadow-map", "1024", "--depth-format", c.depthFormat,
                                                 "--out", (tmp / "out").string()}));
    ASSERT_EQ(run.exitCode, 0) << run.describe();
    const json record = expectRenderOutputs(tmp / "out", "sm");
    EXPECT_EQ(record.value("shadow_map", 0), 1024);
    EXPECT_EQ(record.value("depth_format", ""), c.depthFormat);
    EXPECT_EQ(record.value("memory_bytes", std::uint64_t(0)), c.bytes);
  }
}

// A second run into the same folder replaces the outputs and leaves nothing else.
TEST(CliRender, RerunIntoSameFolderReplacesOutputs) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  ASSERT_EQ(runTestbed(renderArgs(bundledScene("wall.json"), {"--out", out.string()})).exitCode, 0);
  const RunResult run =
      runTestbed(renderArgs(bundledScene("wall.json"), {"--shadow-map", "512", "--out", out.string()}));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  EXPECT_EQ(expectRenderOutputs(out, "sm").value("shadow_map", 0), 512);
}

// The EGL backend (Mesa surfaceless or a GPU) must render the same visibility as OSMesa:
// the technique's output must not depend on how the context was made.
TEST(CliEgl, SameVisibilityAsOsmesa) {
  TempDir tmp;
  const RunResult egl =
      runTestbed(renderArgs(bundledScene("wall.json"), {"--backend", "egl", "--out", (tmp / "egl").string()}));
  if (egl.exitCode != 0 && egl.err.find("no EGL display") != std::string::npos) {
    GTEST_SKIP() << "no EGL display on this machine: " << egl.err;
  }
  ASSERT_EQ(egl.exitCode, 0) << egl.describe();
  const RunResult osmesa = runTestbed(
      renderArgs(bundledScene("wall.json"), {"--backend", "osmesa", "--out", (tmp / "osmesa").string()}));
  ASSERT_EQ(osmesa.exitCode, 0) << osmesa.describe();

  const json eglRecord = expectRenderOutputs(tmp / "egl", "sm");
  ASSERT_TRUE(eglRecord["backend"].is_string()) << eglRecord.dump(2);
  EXPECT_EQ(eglRecord["backend"].get<std::string>().rfind("egl", 0), 0u) << eglRecord["backend"];
  const json osmesaRecord = expectRenderOutputs(tmp / "osmesa", "sm");
  EXPECT_EQ(eglRecord.value("memory_bytes", std::uint64_t(0)), osmesaRecord.value("memory_bytes", std::uint64_t(1)));

  const testbed::ImageF a = testbed::readImage(tmp / "egl" / "sm.exr");
  const testbed::ImageF b = testbed::readImage(tmp / "osmesa" / "sm.exr");
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.channels, b.channels);
  int differing = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    if (!sameFloat(a.pixels[i], b.pixels[i]) && differing++ < 5) {
      ADD_FAILURE() << "pixel " << i % std::size_t(a.width) << "," << i / std::size_t(a.width)
                    << ": egl " << a.pixels[i] << " vs osmesa " << b.pixels[i];
    }
  }
  EXPECT_EQ(differing, 0) << "pixels that differ between egl and osmesa";
}

// A scene the project has never seen: a mesh by path relative to the scene file (not to
// the working directory, which is elsewhere) and an asset mesh by name.
TEST(CliScene, NewSceneWithRelativeMeshPathAndAssetName) {
  TempDir tmp;
  writeFile(tmp / "scenes" / "meshes" / "cube.off", kCubeOff);
  writeFile(tmp / "scenes" / "mine.json", sceneWithObjects(R"(
    {"primitive": "plane", "size": [70, 70]},
    {"mesh": "meshes/cube.off", "scale": 6, "translate": [12, 3, 5]},
    {"mesh": "elephant", "fit": 12, "translate": [-10, 6, 5]})"));
  fs::create_directories(tmp / "cwd");
  RunOptions options;
  options.cwd = tmp / "cwd";
  const RunResult run = runTestbed(renderArgs("../scenes/mine.json", {"--out", "../out"}), options);
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const json record = expectRenderOutputs(tmp / "out", "sm");
  EXPECT_EQ(record.value("scene", ""), "cli-test");
}

// TESTBED_ASSET_DIR replaces the built-in asset folder for meshes named without a path.
TEST(CliScene, AssetDirectoryFromEnvironment) {
  TempDir tmp;
  writeFile(tmp / "assets" / "mycube.off", kCubeOff);
  writeFile(tmp / "scene.json", sceneWithObjects(R"(
    {"primitive": "plane", "size": [70, 70]},
    {"mesh": "mycube", "scale": 6, "translate": [0, 3, 5]})"));
  RunOptions options;
  options.env = {{"TESTBED_ASSET_DIR", (tmp / "assets").string()}};
  const RunResult run = runTestbed(renderArgs(tmp / "scene.json", {"--out", (tmp / "out").string()}), options);
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  expectRenderOutputs(tmp / "out", "sm");
}

// Debian's assimp-testmodels ship invalid/malformed.obj (out-of-range vertex indices) as a
// file that must not crash a reader. OpenMesh reads it (it drops the faces whose indices are
// out of range) so the testbed renders what is left rather than rejecting it.
TEST(CliScene, AssimpMalformedObjIsReadByOpenMesh) {
  const fs::path malformed = "/usr/share/assimp/models/invalid/malformed.obj";
  if (!fs::exists(malformed)) GTEST_SKIP() << malformed << " not installed (Debian assimp-testmodels)";
  TempDir tmp;
  writeFile(tmp / "scene.json", sceneWithObjects(R"({"mesh": ")" + malformed.string() + R"(", "scale": 6})"));
  const RunResult run = runTestbed(renderArgs(tmp / "scene.json", {"--out", (tmp / "out").string()}));
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  const json record = expectRenderOutputs(tmp / "out", "sm");
  EXPECT_GT(record.value("triangles", 0), 0);
}

// ---------------------------------------------------------------------------------------
// list

TEST(CliList, PlainListNamesSm) {
  const RunResult run = runTestbed({"list"});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  // One technique per block, its id first on the line.
  EXPECT_TRUE(run.out.rfind("sm ", 0) == 0 || run.out.find("\nsm ") != std::string::npos) << run.out;
}

TEST(CliList, JsonListDescribesSmAndItsParameters) {
  const RunResult run = runTestbed({"list", "--json"});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  json all;
  ASSERT_NO_THROW(all = json::parse(run.out)) << run.out;
  ASSERT_TRUE(all.is_array()) << run.out;
  const json* sm = nullptr;
  for (const auto& entry : all) {
    ASSERT_TRUE(entry.is_object()) << entry;
    ASSERT_TRUE(entry.contains("id") && entry["id"].is_string()) << entry;
    if (entry["id"] == "sm") sm = &entry;
  }
  ASSERT_NE(sm, nullptr) << "no technique with id \"sm\" in " << run.out;
  EXPECT_EQ(sm->value("family", ""), "shadow_map");
  EXPECT_EQ(sm->value("output", ""), "hard");
  EXPECT_FALSE(sm->value("citation", "").empty());
  ASSERT_TRUE(sm->contains("parameters") && (*sm)["parameters"].is_array()) << *sm;
  ASSERT_FALSE((*sm)["parameters"].empty());
  bool hasBias = false;
  for (const auto& p : (*sm)["parameters"]) {
    EXPECT_TRUE(p.contains("name") && p["name"].is_string()) << p;
    EXPECT_TRUE(p.contains("type") && p["type"].is_string()) << p;
    EXPECT_TRUE(p.contains("default")) << p;
    if (p.value("name", "") == "bias") {
      hasBias = true;
      EXPECT_EQ(p.value("type", ""), "float");
      EXPECT_EQ(p.value("min", 0.0), -1.0);
      EXPECT_EQ(p.value("max", 0.0), 1.0);
    }
  }
  EXPECT_TRUE(hasBias) << *sm;
}

// ---------------------------------------------------------------------------------------
// Bad input: exit code 2, one line on stderr naming the file/option/field, and nothing
// written to --out.

struct BadCase {
  std::string name;
  std::vector<std::string> args;       // without --out; the test adds a fresh one
  std::vector<std::string> mustName;   // every one of these appears in the error line
  std::vector<std::string> nameOneOf;  // and, when not empty, at least one of these
};

void expectRejected(const BadCase& c, const fs::path& out) {
  SCOPED_TRACE(c.name);
  std::vector<std::string> args = c.args;
  args.push_back("--out");
  args.push_back(out.string());
  const RunResult run = runTestbed(args);
  EXPECT_EQ(run.exitCode, 2) << run.describe();
  // Exactly one non-empty line: the text ends in its only newline.
  EXPECT_GT(run.err.size(), 1u) << run.describe();
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << run.describe();
  EXPECT_EQ(run.err.back(), '\n') << run.describe();
  EXPECT_EQ(run.err.rfind("testbed: ", 0), 0u) << run.describe();
  for (const auto& text : c.mustName) EXPECT_NE(run.err.find(text), std::string::npos) << "names \"" << text << "\"\n" << run.describe();
  if (!c.nameOneOf.empty()) {
    bool any = false;
    std::string all;
    for (const auto& text : c.nameOneOf) {
      any = any || run.err.find(text) != std::string::npos;
      all += " \"" + text + "\"";
    }
    EXPECT_TRUE(any) << "names one of" << all << "\n" << run.describe();
  }
  EXPECT_EQ(filesIn(out), std::vector<std::string>{}) << "files left in --out";
}

TEST(CliBadInput, OptionsAndScenesAreRejectedWithOneLine) {
  TempDir tmp;
  const fs::path wall = bundledScene("wall.json");
  auto scene = [&](const std::string& file, const std::string& text) {
    writeFile(tmp / file, text);
    return tmp / file;
  };
  const std::string plane = R"({"primitive": "plane", "size": [70, 70]})";
  writeFile(tmp / "meshes" / "empty.off", "");

  const std::vector<BadCase> cases = {
      // Scene files
      {"missing scene file", renderArgs(tmp / "no-such-scene.json", {}), {"no-such-scene.json"}, {}},
      {"unknown key",
       renderArgs(scene("unknown-key.json", sceneWithObjects(R"({"primitive": "plane", "size": [70, 70], "colour": 1})")), {}),
       {"unknown-key.json", "objects[0].colour"}, {}},
      // JSON has no NaN/Inf; 1e999 is the way such a value arrives (it overflows to Inf).
      {"infinite number 1e999",
       renderArgs(scene("inf.json", sceneWithObjects(R"({"primitive": "plane", "size": [70, 70], "scale": 1e999})")), {}),
       {"inf.json"}, {"objects[0].scale", "line "}},
      {"NaN literal",
       renderArgs(scene("nan.json", sceneWithObjects(R"({"primitive": "plane", "size": [70, 70], "scale": NaN})")), {}),
       {"nan.json"}, {"objects[0].scale", "line "}},
      {"wrong type",
       renderArgs(scene("wrong-type.json", sceneWithObjects(R"({"primitive": "plane", "size": [70, 70], "scale": "big"})")), {}),
       {"wrong-type.json", "objects[0].scale"}, {}},
      {"empty objects array", renderArgs(scene("no-objects.json", sceneWithObjects("")), {}),
       {"no-objects.json", "objects"}, {}},
      {"empty mesh file",
       renderArgs(scene("empty-mesh.json", sceneWithObjects(plane + R"(, {"mesh": "meshes/empty.off"})")), {}),
       {"empty-mesh.json", "objects[1].mesh", "empty.off"}, {}},
      {"missing mesh file",
       renderArgs(scene("missing-mesh.json", sceneWithObjects(plane + R"(, {"mesh": "meshes/missing.off"})")), {}),
       {"missing-mesh.json", "objects[1].mesh", "missing.off"}, {}},
      // Common options
      {"--size 0x0", renderArgs(wall, {"--size", "0x0"}), {"--size"}, {}},
      {"--size 100000x100000", renderArgs(wall, {"--size", "100000x100000"}), {"--size"}, {}},
      {"--size garbage", renderArgs(wall, {"--size", "garbage"}), {"--size"}, {}},
      {"--shadow-map 0", renderArgs(wall, {"--shadow-map", "0"}), {"--shadow-map"}, {}},
      {"--shadow-map 100000", renderArgs(wall, {"--shadow-map", "100000"}), {"--shadow-map"}, {}},
      {"--shadow-map abc", renderArgs(wall, {"--shadow-map", "abc"}), {"--shadow-map"}, {}},
      {"--depth-format 8", renderArgs(wall, {"--depth-format", "8"}), {"--depth-format"}, {}},
      {"--backend nope", renderArgs(wall, {"--backend", "nope"}), {"--backend", "nope"}, {}},
      {"--repeat 0", renderArgs(wall, {"--repeat", "0"}), {"--repeat"}, {}},
      // Technique and parameters
      {"unknown --technique", renderArgs(wall, {"--technique", "nope"}), {"--technique", "nope"}, {}},
      {"--set unknown parameter", renderArgs(wall, {"--set", "nope=1"}), {"--set", "nope"}, {}},
      {"--set wrong type", renderArgs(wall, {"--set", "bias=abc"}), {"--set", "bias"}, {}},
      {"--set nan", renderArgs(wall, {"--set", "bias=nan"}), {"--set", "bias"}, {}},
      {"--set out of range", renderArgs(wall, {"--set", "bias=5"}), {"--set", "bias"}, {}},
      {"--set without =", renderArgs(wall, {"--set", "bias"}), {"--set", "bias"}, {}},
      {"--set twice", renderArgs(wall, {"--set", "bias=0.1", "--set", "bias=0.2"}), {"--set", "bias"}, {}},
      // Command line shape
      {"unknown subcommand option", renderArgs(wall, {"--bogus"}), {"--bogus"}, {}},
      {"missing --scene", {"render", "--technique", "sm"}, {"--scene"}, {}},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) expectRejected(cases[i], tmp / ("out-" + std::to_string(i)));
}

// A mistyped subcommand is bad input like any other, and the line says which word was
// not understood (not just that a subcommand is missing).
TEST(CliBadInput, UnknownSubcommandIsNamed) {
  TempDir tmp;
  expectRejected({"unknown subcommand", {"frobnicate"}, {"frobnicate"}, {}}, tmp / "out");
}

// Debian's assimp-testmodels: files made to break model readers (empty, lying headers,
// too few elements). Referenced by absolute path from a scene.
TEST(CliBadInput, AssimpInvalidModelsAreRejected) {
  const fs::path models = "/usr/share/assimp/models";
  if (!fs::is_directory(models)) GTEST_SKIP() << models << " not installed (Debian assimp-testmodels)";
  TempDir tmp;
  // malformed.obj is read by OpenMesh: see CliScene.AssimpMalformedObjIsReadByOpenMesh.
  const std::vector<std::string> files = {"invalid/empty.off", "invalid/empty.ply", "invalid/empty.obj",
                                          "invalid/OutOfMemory.off", "OFF/invalid.off"};
  std::vector<BadCase> cases;
  for (const auto& file : files) {
    const fs::path mesh = models / file;
    if (!fs::exists(mesh)) {
      ADD_FAILURE() << mesh << " missing from an installed assimp-testmodels";
      continue;
    }
    const std::string sceneName = "assimp-" + std::to_string(cases.size()) + ".json";
    writeFile(tmp / sceneName, sceneWithObjects(R"({"primitive": "plane", "size": [70, 70]}, {"mesh": ")" +
                                                mesh.string() + R"("})"));
    cases.push_back({file, renderArgs(tmp / sceneName, {}), {sceneName, "objects[1].mesh", mesh.filename().string()}, {}});
  }
  for (std::size_t i = 0; i < cases.size(); ++i) expectRejected(cases[i], tmp / ("out-" + std::to_string(i)));
}

// ---------------------------------------------------------------------------------------
// Failed runs must not touch earlier results in --out.

// Earlier outputs in --out, to be compared after a failed run.
struct OldOutputs {
  explicit OldOutputs(fs::path folder) : dir(std::move(folder)) {
    writeFile(dir / "sm.json", R"({"technique": "sm", "note": "an earlier run"})" "\n");
    writeFile(dir / "sm.png", "not really a png, from an earlier run\n");
  }
  void expectUntouched() const {
    EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"sm.json", "sm.png"}));
    EXPECT_TRUE(fileHolds(dir / "sm.json", R"({"technique": "sm", "note": "an earlier run"})" "\n"));
    EXPECT_TRUE(fileHolds(dir / "sm.png", "not really a png, from an earlier run\n"));
  }
  fs::path dir;
};

TEST(CliRender, BadInputLeavesEarlierOutputsUntouched) {
  TempDir tmp;
  writeFile(tmp / "bad.json", sceneWithObjects(R"({"primitive": "plane", "size": [70, -1]})"));
  // Rejected while parsing options, while loading the scene, and after the GL context is
  // up (the size limit depends on the context).
  const std::vector<std::pair<std::string, std::vector<std::string>>> failures = {
      {"--set bias=5", renderArgs(bundledScene("wall.json"), {"--set", "bias=5"})},
      {"bad scene", renderArgs(tmp / "bad.json", {})},
      {"--size 100000x100000", renderArgs(bundledScene("wall.json"), {"--size", "100000x100000"})},
  };
  for (const auto& [name, baseArgs] : failures) {
    SCOPED_TRACE(name);
    const OldOutputs old(tmp / "out");
    std::vector<std::string> args = baseArgs;
    args.insert(args.end(), {"--out", old.dir.string()});
    const RunResult run = runTestbed(args);
    EXPECT_EQ(run.exitCode, 2) << run.describe();
    old.expectUntouched();
  }
}

// The outputs of one run are committed together ("nothing half-written"): when one of them
// cannot be put in place (here a folder is in the way of sm.json), the run fails and the
// earlier sm.png stays as it was, with no new sm.exr beside it and no .partial files.
TEST(CliRender, FailedCommitLeavesNoHalfWrittenSet) {
  TempDir tmp;
  const fs::path out = tmp / "out";
  writeFile(out / "sm.png", "not really a png, from an earlier run\n");
  writeFile(out / "sm.json" / "in-the-way", "a folder where sm.json should go\n");
  const RunResult run = runTestbed(renderArgs(bundledScene("wall.json"), {"--out", out.string()}));
  EXPECT_NE(run.exitCode, 0) << run.describe();
  EXPECT_EQ(filesIn(out), (std::vector<std::string>{"sm.json", "sm.png"}));
  EXPECT_TRUE(fileHolds(out / "sm.png", "not really a png, from an earlier run\n"));
}

// --out naming an existing file: the run fails, the file is left alone, nothing is
// written beside it.
TEST(CliRender, OutThatIsAFileFailsAndLeavesItAlone) {
  TempDir tmp;
  writeFile(tmp / "taken", "a file, not a folder\n");
  const RunResult run = runTestbed(renderArgs(bundledScene("wall.json"), {"--out", (tmp / "taken").string()}));
  EXPECT_NE(run.exitCode, 0) << run.describe();
  EXPECT_NE(run.err.find("taken"), std::string::npos) << run.describe();
  EXPECT_TRUE(fileHolds(tmp / "taken", "a file, not a folder\n"));
  EXPECT_EQ(filesIn(tmp.path()), std::vector<std::string>{"taken"});
}

// compare: the ground truth first (its error against itself all zeros), every chosen
// technique with a complete error block, and the report files people look at.
TEST(CliCompare, WritesRecordsReportGridAndPlot) {
  TempDir tmp;
  const fs::path out = tmp / "cmp";
  const RunResult run = runTestbed({"compare", "--scene", bundledScene("wall.json").string(), "--techniques", "sm",
                                    "--size", "160x90", "--shadow-map", "256", "--area-samples", "4", "--out",
                                    out.string()});
  ASSERT_EQ(run.exitCode, 0) << run.describe();
  for (const char* file : {"metrics.json", "report.md", "grid.png", "speed_vs_error.svg", "groundtruth.exr",
                           "groundtruth.json", "area.exr", "sm.exr", "sm.json", "sm.png"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const json all = json::parse(readFile(out / "metrics.json"));
  ASSERT_TRUE(all.is_array());
  ASSERT_EQ(all.size(), 3u);  // groundtruth, area, sm
  EXPECT_EQ(all[0]["technique"], "groundtruth");
  for (const char* key : {"mismatch_pct", "edge_mismatch_pct", "rmse", "leak_pct", "overestimation_pct"})
    EXPECT_EQ(all[0]["error"][key], 0.0) << key;
  EXPECT_EQ(all[0]["error"]["boundary_px"]["mean"], 0.0);
  const json& sm = all[2];
  EXPECT_EQ(sm["technique"], "sm");
  for (const char* key : {"mismatch_pct", "edge_mismatch_pct", "rmse", "leak_pct", "overestimation_pct", "soft_rmse"})
    EXPECT_TRUE(sm["error"][key].is_number()) << key;
  EXPECT_GT(sm["error"]["mismatch_pct"].get<double>(), 0.0) << "a 256² map on 160x90 pixels is not exact";
  const std::string report = readFile(out / "report.md");
  EXPECT_NE(report.find("| technique | GPU ms (queries) | wall ms | × sm |"), std::string::npos);
  EXPECT_NE(report.find("| `sm` |"), std::string::npos);
  EXPECT_NE(readFile(out / "speed_vs_error.svg").find("<circle"), std::string::npos);
  const testbed::ImageF grid = testbed::readImage(out / "grid.png");
  EXPECT_GT(grid.width, 480);
  EXPECT_EQ(grid.channels, 3);
  // Progress: one line per step on stderr.
  EXPECT_NE(run.err.find("[1/3] groundtruth"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("[3/3] sm"), std::string::npos) << run.err;
}

TEST(CliCompare, RoutesParametersPerTechniqueAndRejectsUnknownOnes) {
  TempDir tmp;
  const RunResult bad = runTestbed({"compare", "--scene", bundledScene("wall.json").string(), "--techniques", "sm",
                                    "--set", "bias=0.1", "--out", (tmp / "x").string()});
  EXPECT_EQ(bad.exitCode, 2) << bad.describe();
  EXPECT_NE(bad.err.find("technique.name=value"), std::string::npos) << bad.err;
  const RunResult unknown = runTestbed({"compare", "--scene", bundledScene("wall.json").string(), "--techniques",
                                        "sm,nope", "--out", (tmp / "y").string()});
  EXPECT_EQ(unknown.exitCode, 2) << unknown.describe();
  EXPECT_NE(unknown.err.find("nope"), std::string::npos) << unknown.err;
  EXPECT_FALSE(fs::exists(tmp / "x"));
  EXPECT_FALSE(fs::exists(tmp / "y"));
}

// compare --reference soft|both on a tiny frame. The soft grid's error maps are drawn
// against the area-light reference, so `soft`'s grid.png is the very image `both` writes as
// grid_soft.png, and it differs from the hard grid.png; every record says which reference
// each of its metrics was measured against.
std::vector<std::string> softCompareArgs(const fs::path& scene, const std::string& reference, const fs::path& out) {
  return {"compare",      "--scene", scene.string(), "--techniques", "sm",        "--size",  "160x90",
          "--shadow-map", "128",     "--area-samples", "8",         "--reference", reference, "--out", out.string()};
}

TEST(CliCompare, SoftAndBothReferencesDrawTheSoftGrid) {
  TempDir tmp;
  const RunResult soft = runTestbed(softCompareArgs(bundledScene("wall.json"), "soft", tmp / "soft"));
  ASSERT_EQ(soft.exitCode, 0) << soft.describe();
  const RunResult both = runTestbed(softCompareArgs(bundledScene("wall.json"), "both", tmp / "both"));
  ASSERT_EQ(both.exitCode, 0) << both.describe();
  EXPECT_TRUE(fs::exists(tmp / "soft" / "grid.png"));
  EXPECT_FALSE(fs::exists(tmp / "soft" / "grid_soft.png")) << "soft alone has one grid";
  EXPECT_TRUE(fs::exists(tmp / "soft" / "area.exr"));
  for (const char* file : {"grid.png", "grid_soft.png", "area.exr"}) EXPECT_TRUE(fs::exists(tmp / "both" / file)) << file;

  const testbed::ImageF softGrid = testbed::readImage(tmp / "soft" / "grid.png");
  const testbed::ImageF bothSoftGrid = testbed::readImage(tmp / "both" / "grid_soft.png");
  const testbed::ImageF bothHardGrid = testbed::readImage(tmp / "both" / "grid.png");
  ASSERT_GT(softGrid.width, 480);
  ASSERT_EQ(softGrid.width, bothSoftGrid.width);
  ASSERT_EQ(softGrid.height, bothSoftGrid.height);
  ASSERT_EQ(bothHardGrid.pixels.size(), bothSoftGrid.pixels.size());
  // The row label holds each run's own timings; the images below it are the same. Where the
  // images start is where one run's hard and soft grids (same labels) first differ.
  auto rowsDiffer = [](const testbed::ImageF& a, const testbed::ImageF& b, int y) {
    const std::size_t row = std::size_t(a.width) * a.channels;
    return !std::equal(a.pixels.begin() + y * row, a.pixels.begin() + (y + 1) * row, b.pixels.begin() + y * row);
  };
  int imagesTop = 0;
  while (imagesTop < softGrid.height && !rowsDiffer(bothHardGrid, bothSoftGrid, imagesTop)) ++imagesTop;
  ASSERT_LT(imagesTop, softGrid.height) << "error maps against the shadow volumes differ from the soft ones";
  for (int y = imagesTop; y < softGrid.height; ++y)
    ASSERT_FALSE(rowsDiffer(softGrid, bothSoftGrid, y)) << "row " << y << ": soft's grid.png is both's grid_soft.png";

  const json all = json::parse(readFile(tmp / "soft" / "metrics.json"));
  ASSERT_EQ(all.size(), 3u);  // groundtruth, area, sm
  EXPECT_EQ(all[1]["technique"], "area");
  const json& sm = all[2];
  ASSERT_EQ(sm["technique"], "sm");
  for (const char* key : {"soft_rmse", "soft_penumbra_mae", "soft_outside_mae", "soft_umbra_leak"}) {
    ASSERT_TRUE(sm["error"][key].is_number()) << key << ": " << sm.dump(2);
    const double value = sm["error"][key].get<double>();
    EXPECT_GE(value, 0.0) << key;
    EXPECT_LE(value, 1.0) << key;
    EXPECT_EQ(sm["error"]["reference"][key], "soft") << key;
  }
  // sm's hard edge against a radius-2 light: wrong inside the penumbra, not zero there.
  EXPECT_GT(sm["error"]["soft_penumbra_mae"].get<double>(), 0.0);
  EXPECT_EQ(sm["error"]["reference"]["rmse"], "hard");
  EXPECT_EQ(sm["error"]["reference"]["mismatch_pct"], "hard");
}

// A light without a radius has no area-light reference: exit 2 with one line naming the scene
// and light.radius, nothing written, for both soft references.
TEST(CliCompare, SoftReferenceRefusesALightWithoutRadius) {
  TempDir tmp;
  json scene = json::parse(readFile(bundledScene("wall.json")));
  scene["light"].erase("radius");
  const fs::path file = writeFile(tmp / "point_light.json", scene.dump(2));
  for (const char* reference : {"soft", "both"}) {
    const fs::path out = tmp / (std::string("out_") + reference);
    const RunResult run = runTestbed(softCompareArgs(file, reference, out));
    EXPECT_EQ(run.exitCode, 2) << run.describe();
    EXPECT_NE(run.err.find("light.radius"), std::string::npos) << run.err;
    EXPECT_NE(run.err.find("point_light.json"), std::string::npos) << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << "one line: " << run.err;
    EXPECT_FALSE(fs::exists(out)) << reference;
  }
}

}  // namespace
