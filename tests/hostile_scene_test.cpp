// Hostile scene files, generated per class (syntax, nesting, numbers, degenerate camera
// vectors, ranges, file kinds): each must give exit 2, exactly one stderr line naming the
// file (and the key, where there is one), and nothing in --out. They fail before any GL
// work, so each run takes milliseconds.
#include <sys/stat.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/scene/scene.h"
#include "tests/cli_helpers.h"

namespace {

namespace fs = std::filesystem;
using namespace testbed::test;

// The camera, light and objects of a small valid scene; `patch` replaces parts of it.
std::string sceneText(const std::string& camera = R"({"eye": [0, 30, -45], "target": [0, 0, 5], "fov_y": 45, "near": 1, "far": 500})",
                      const std::string& objects = R"([{"primitive": "plane", "size": [70, 70]}])") {
  return R"({"camera": )" + camera +
         R"(, "light": {"type": "spot", "eye": [0, 60, 60], "target": [0, 0, 0], "fov": 60, "near": 30, "far": 200}, "objects": )" +
         objects + "}";
}

std::string camera(const std::string& fields) {
  return "{" + fields + "}";
}

struct Case {
  std::string name, text;
  std::string key;  // the key path the line must name, "" when none applies
};

// Each case is loaded in-process (the parser is what is under test, and a subprocess per
// case would cost the suite minutes); the first of each list also goes through the binary
// for the exit code, the one line and the empty --out.
void expectAllRejected(const std::vector<Case>& cases) {
  TempDir tmp;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    SCOPED_TRACE(c.name);
    const fs::path scene = tmp / ("case-" + std::to_string(i) + ".json");
    writeFile(scene, c.text);
    if (const auto what = inputErrorOf([&] { testbed::loadScene(scene); })) {
      EXPECT_EQ(what->rfind(scene.string() + ": ", 0), 0u) << *what;
      if (!c.key.empty()) EXPECT_NE(what->find(c.key), std::string::npos) << "names " << c.key << ": " << *what;
      EXPECT_LT(what->size(), 400u) << "a short line, not a dump of the input";
    }
    if (i > 0) continue;
    const fs::path out = tmp / ("out-" + std::to_string(i));
    const RunResult run = runTestbed({"render", "--scene", scene.string(), "--technique", "sm", "--size", "160x90",
                                      "--shadow-map", "128", "--out", out.string()});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_NE(run.err.find(scene.filename().string()), std::string::npos) << run.describe();
    EXPECT_FALSE(fs::exists(out)) << "nothing written";
  }
}

TEST(HostileScene, SyntaxErrorsNameTheLine) {
  const std::string good = sceneText();
  std::vector<Case> cases = {
      {"empty file", "", ""},
      {"only whitespace", " \n\t\n", ""},
      {"truncated", good.substr(0, good.size() / 2), "line "},
      {"trailing garbage", good + " x", "line "},
      {"trailing comma", good.substr(0, good.size() - 1) + ",}", "line "},
      {"comment", "// a scene\n" + good, "line "},
      {"single quotes", "{'camera': 1}", "line "},
      {"NaN literal", sceneText(camera(R"("eye": [NaN, 0, 0], "target": [0, 0, 1])")), "line "},
      {"Infinity literal", sceneText(camera(R"("eye": [Infinity, 0, 0], "target": [0, 0, 1])")), "line "},
      {"invalid UTF-8", sceneText().insert(1, "\"name\": \"\xff\xfe\", "), "line "},
      {"raw newline in a string", sceneText().insert(1, "\"name\": \"a\nb\", "), "line "},
      {"NUL byte", std::string("{\0}", 3), "line "},
      {"UTF-16", std::string("\xff\xfe{\0}\0", 6), "line "},
  };
  expectAllRejected(cases);
}

TEST(HostileScene, DeepNestingIsRefusedWithoutOverflowingTheStack) {
  expectAllRejected({
      {"70000 nested arrays", std::string(70000, '[') + std::string(70000, ']'), ""},
      {"70000 nested objects", [] {
         std::string text;
         for (int i = 0; i < 70000; ++i) text += "{\"a\":";
         return text + "1" + std::string(70000, '}');
       }(), ""},
      {"deep inside a valid key", sceneText(camera(R"("eye": )" + std::string(5000, '[') + std::string(5000, ']'))), ""},
      {"wide array", "[" + [] {
         std::string items;
         for (int i = 0; i < 200000; ++i) items += "0,";
         return items;
       }() + "0]", ""},
  });
}

TEST(HostileScene, NumbersOutsideFloatsAndDuplicateKeys) {
  auto withScale = [](const std::string& scale) {
    return sceneText(R"({"eye": [0, 30, -45], "target": [0, 0, 5]})",
                     R"([{"primitive": "plane", "size": [70, 70], "scale": )" + scale + "}]");
  };
  expectAllRejected({
      {"1e999", withScale("1e999"), "objects[0].scale"},
      {"-1e999", withScale("-1e999"), "objects[0].scale"},
      {"1e39 (beyond float)", withScale("1e39"), "objects[0].scale"},
      {"1e-50 (0 as a float)", withScale("1e-50"), "objects[0].scale"},
      {"negative zero", withScale("-0.0"), "objects[0].scale"},
      {"a string", withScale("\"2\""), "objects[0].scale"},
      {"huge integer segments", sceneText(R"({"eye": [0, 30, -45], "target": [0, 0, 5]})",
                                          R"([{"primitive": "sphere", "radius": 1, "segments": 1e20}])"),
       "objects[0].segments"},
      {"fractional segments", sceneText(R"({"eye": [0, 30, -45], "target": [0, 0, 5]})",
                                        R"([{"primitive": "sphere", "radius": 1, "segments": 3.5}])"),
       "objects[0].segments"},
      {"duplicate top-level key", sceneText().insert(1, "\"objects\": [], "), "objects"},
      {"duplicate nested key", sceneText(camera(R"("eye": [0, 30, -45], "eye": [0, 1, 2], "target": [0, 0, 5])")),
       "camera.eye"},
  });
}

TEST(HostileScene, DegenerateCameraValuesNameTheFieldAndTheReason) {
  expectAllRejected({
      {"far 2e38", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "far": 2e38)")), "camera.far"},
      {"near 1e-30", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "near": 1e-30, "far": 10)")),
       "camera.far"},
      {"near 1e30 far 1e31", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "near": 1e30, "far": 1e31)")),
       "camera.far"},
      {"near 100 far 100.00001",
       sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "near": 100, "far": 100.00001)")), "camera.far"},
      {"far below near", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "near": 10, "far": 5)")),
       "camera.far"},
      {"fov_y 1e-38", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "fov_y": 1e-38)")), "camera.fov_y"},
      {"fov_y 179.9999", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "fov_y": 179.9999)")),
       "camera.fov_y"},
      {"fov_y 180", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "fov_y": 180)")), "camera.fov_y"},
      {"fov_y 0", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "fov_y": 0)")), "camera.fov_y"},
      {"eye equals target", sceneText(camera(R"("eye": [1, 2, 3], "target": [1, 2, 3])")), "camera.target"},
      {"eye 1e-30 from target", sceneText(camera(R"("eye": [0, 0, 0], "target": [1e-30, 0, 0])")), "camera.target"},
      {"eye 1e-3 from a far target", sceneText(camera(R"("eye": [1e6, 0, 0], "target": [1000000.001, 0, 0])")),
       "camera.target"},
      {"up parallel to view", sceneText(camera(R"("eye": [0, 10, 0], "target": [0, 0, 0], "up": [0, 1, 0])")),
       "camera.up"},
      {"up zero", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "up": [0, 0, 0])")), "camera.up"},
      {"up 1e-30", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "up": [0, 1e-30, 0])")), "camera.up"},
      {"eye of two numbers", sceneText(camera(R"("eye": [0, 30], "target": [0, 0, 5])")), "camera.eye"},
  });
}

// Finite but huge camera placements: before these checks they rendered an empty image with
// exit 0. The eye where float spacing reaches the near plane, a target beyond far, and the
// same through animation keys (checked at every frame, the frame named).
TEST(HostileScene, HugeCameraPlacementsAreRefusedBeforeRendering) {
  auto animated = [&](const std::string& keys) {
    std::string text = sceneText();
    text.insert(text.size() - 1, R"(, "animation": {"frames": 4, "camera": )" + keys + "}");
    return text;
  };
  expectAllRejected({
      {"eye at 1e30", sceneText(camera(R"("eye": [0, 1e30, -45], "target": [0, 0, 5])")), "camera.eye"},
      {"eye where float spacing is 2 (near 1)", sceneText(camera(R"("eye": [0, 2e7, 0], "target": [0, 0, 5], "up": [0, 0, 1])")),
       "camera.eye"},
      {"target beyond far", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5000], "far": 500)")),
       "camera.target"},
      {"animation key with the eye at 1e30",
       animated(R"([{"frame": 0, "eye": [0, 30, -45]}, {"frame": 3, "eye": [0, 30, -1e30]}])"), "animation.camera.eye"},
      {"animation key with the target onto the eye",
       animated(R"([{"frame": 0, "target": [0, 0, 5]}, {"frame": 2, "target": [0, 30, -45]}])"),
       "animation.camera.target"},
      {"animation key with the target beyond far",
       animated(R"([{"frame": 0, "target": [0, 0, 5]}, {"frame": 3, "target": [0, 0, 4000]}])"), "at frame"},
  });
}

TEST(HostileScene, StructureAndRanges) {
  const std::string cam = R"({"eye": [0, 30, -45], "target": [0, 0, 5]})";
  expectAllRejected({
      {"top level array", "[]", ""},
      {"top level number", "42", ""},
      {"camera missing", R"({"light": {"type": "spot", "eye": [0,1,0]}, "objects": []})", "camera"},
      {"unknown camera key", sceneText(camera(R"("eye": [0, 30, -45], "target": [0, 0, 5], "fovy": 40)")), "camera.fovy"},
      {"odd key with a newline", sceneText(camera("\"eye\": [0, 30, -45], \"target\": [0, 0, 5], \"a\\nb\": 1")), "camera"},
      {"objects not an array", sceneText(cam, R"({"primitive": "plane"})"), "objects"},
      {"object not an object", sceneText(cam, "[3]"), "objects[0]"},
      {"unknown primitive", sceneText(cam, R"([{"primitive": "teapot"}])"), "objects[0].primitive"},
      {"subdivide 5", sceneText(cam, R"([{"primitive": "plane", "size": [1, 1], "subdivide": 5}])"), "objects[0].subdivide"},
      {"too many triangles", sceneText(cam, R"([{"primitive": "plane", "size": [1, 1], "segments": 1024, "subdivide": 4}])"),
       "objects[0]"},
      {"torus minor above major", sceneText(cam, R"([{"primitive": "torus", "major": 1, "minor": 2}])"),
       "objects[0].minor"},
      {"translate overflowing after scale",
       sceneText(cam, R"([{"primitive": "plane", "size": [1e30, 1e30], "scale": 1e30}])"), "objects[0]"},
      {"mesh that is a folder", sceneText(cam, R"([{"mesh": "/tmp"}])"), "objects[0].mesh"},
      {"mesh /dev/zero", sceneText(cam, R"([{"mesh": "/dev/zero"}])"), "objects[0].mesh"},
  });
}

// Files that are not scene files at all: a folder, a device, a FIFO (which must not block),
// a missing file; and a path with a newline, which the line must escape.
TEST(HostileScene, SceneFilesThatAreNotRegularFilesAreRefusedAtOnce) {
  TempDir tmp;
  ASSERT_EQ(::mkfifo((tmp / "fifo.json").c_str(), 0600), 0);
  writeFile(tmp / "new\nline.json", "{");
  for (const fs::path& scene : {fs::path("/dev/zero"), fs::path("/dev/null"), tmp / "fifo.json", tmp.path(),
                                tmp / "missing.json", tmp / "new\nline.json"}) {
    SCOPED_TRACE(scene.string());
    // The default timeout only guards against a run that blocks; a refusal returns at once.
    const RunResult run = runTestbed({"render", "--scene", scene.string(), "--technique", "sm", "--out",
                                      (tmp / "out").string()});
    EXPECT_TRUE(rejectedWithOneLine(run));
    EXPECT_FALSE(fs::exists(tmp / "out"));
  }
}

}  // namespace
