#include <OpenMesh/Core/IO/MeshIO.hh>  // must precede the mesh type header

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/scene/scene.h"
#include "tests/cli_helpers.h"
#include "testbed_test_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const char* const kTetrahedronOff =
    "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

json goodScene() {
  return json::parse(R"({
    "name": "test-scene",
    "comment": "a box above a floor",
    "camera": {"eye": [0, 41, -50], "target": [0, 16, -10], "fov_y": 50, "near": 0.5, "far": 500},
    "light": {"type": "spot", "eye": [10, 130, 100], "target": [0, 0, 0], "radius": 2.0,
              "comment": "overhead"},
    "objects": [
      {"primitive": "box", "size": [2, 2, 2], "translate": [0, 5, 0], "comment": "occluder"},
      {"primitive": "plane", "size": [60, 40], "translate": [0, -8, 0]}
    ]
  })");
}

struct Box {
  glm::vec3 lo{1e30f}, hi{-1e30f};
  glm::vec3 size() const { return hi - lo; }
  glm::vec3 centre() const { return (lo + hi) * 0.5f; }
};

Box bounds(const TriMesh& mesh) {
  Box box;
  for (const auto v : mesh.vertices()) {
    const auto p = mesh.point(v);
    box.lo = glm::min(box.lo, glm::vec3(p[0], p[1], p[2]));
    box.hi = glm::max(box.hi, glm::vec3(p[0], p[1], p[2]));
  }
  return box;
}

void expectVec(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-4f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// Sets an environment variable for one test and restores the old value afterwards.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

class SceneParser : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) const {
    return test::writeFile(dir_ / name, text);
  }
  fs::path writeScene(const std::string& name, const json& scene) const {
    return write(name, scene.dump(2));
  }

  // loadScene must throw one line "<file>: <key>: ..." that contains `problem`.
  void expectError(const fs::path& file, const std::string& key, const std::string& problem) const {
    try {
      loadScene(file);
      ADD_FAILURE() << "expected an InputError for " << key;
    } catch (const InputError& e) {
      const std::string message = e.what();
      const std::string prefix = file.string() + ": " + (key.empty() ? "" : key + ": ");
      EXPECT_EQ(message.rfind(prefix, 0), 0u) << message << "\nexpected prefix: " << prefix;
      EXPECT_NE(message.find(problem), std::string::npos) << message << "\nexpected: " << problem;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }

  // Applies `edit` to the good scene, saves it and expects the error.
  void expectBad(const std::function<void(json&)>& edit, const std::string& key,
                 const std::string& problem) const {
    json scene = goodScene();
    edit(scene);
    expectError(writeScene("bad.json", scene), key, problem);
  }

  test::TempDir dir_{"testbed-scene"};
};

TEST_F(SceneParser, GoodSceneParsesWithValuesAndDefaults) {
  const fs::path file = writeScene("good.json", goodScene());
  const Scene scene = loadScene(file);
  EXPECT_EQ(scene.name, "test-scene");
  EXPECT_EQ(scene.file, file);
  expectVec(scene.camera.eye, {0, 41, -50});
  expectVec(scene.camera.target, {0, 16, -10});
  expectVec(scene.camera.up, {0, 1, 0});  // default
  EXPECT_FLOAT_EQ(scene.camera.fovYDegrees, 50.0f);
  EXPECT_FLOAT_EQ(scene.camera.nearPlane, 0.5f);
  EXPECT_FLOAT_EQ(scene.camera.farPlane, 500.0f);
  EXPECT_EQ(scene.light.type, LightType::Spot);
  expectVec(scene.light.eye, {10, 130, 100});
  EXPECT_FLOAT_EQ(scene.light.fovDegrees, 45.0f);  // defaults
  EXPECT_FLOAT_EQ(scene.light.nearPlane, 1.0f);
  EXPECT_FLOAT_EQ(scene.light.farPlane, 1000.0f);
  EXPECT_FLOAT_EQ(scene.light.radius, 2.0f);
  ASSERT_EQ(scene.objects.size(), 2u);
  EXPECT_EQ(scene.objects[0].label, "objects[0] (primitive box)");
  EXPECT_EQ(scene.objects[1].label, "objects[1] (primitive plane)");
  const Box box = bounds(scene.objects[0].mesh);
  expectVec(box.centre(), {0, 5, 0});
  expectVec(box.size(), {2, 2, 2});
  const Box plane = bounds(scene.objects[1].mesh);
  expectVec(plane.size(), {60, 0, 40});
  EXPECT_FLOAT_EQ(plane.centre().y, -8.0f);
}

TEST_F(SceneParser, NameDefaultsToFileStemAndDirectionalLightParses) {
  json scene = goodScene();
  scene.erase("name");
  scene["light"] = json::parse(R"({"type": "directional", "direction": [0, -2, 0], "extent": 30})");
  const Scene parsed = loadScene(writeScene("my-scene.json", scene));
  EXPECT_EQ(parsed.name, "my-scene");
  EXPECT_EQ(parsed.light.type, LightType::Directional);
  expectVec(parsed.light.direction, {0, -1, 0});  // normalised
  expectVec(parsed.light.target, {0, 0, 0});
  EXPECT_FLOAT_EQ(parsed.light.extent, 30.0f);
  EXPECT_FLOAT_EQ(parsed.light.radius, 0.0f);
}

TEST_F(SceneParser, ParseSceneWorksOnADocument) {
  const Scene scene = parseScene(goodScene(), dir_ / "virtual.json");
  EXPECT_EQ(scene.objects.size(), 2u);
  json bad = goodScene();
  bad["camera"]["eye"][1] = std::nan("");
  try {
    parseScene(bad, "virtual.json");
    ADD_FAILURE() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "virtual.json: camera.eye[1]: not a finite number");
  }
}

// The checked JSON reader's rule (io/json_reader.h): a whole number however written.
TEST_F(SceneParser, WholeNumbersMayBeWrittenAsFloats) {
  json scene = goodScene();
  scene["objects"][1]["segments"] = 3.0;
  EXPECT_EQ(parseScene(scene, dir_ / "virtual.json").objects[1].mesh.n_faces(), 18u);  // 3 × 3 quads
}

TEST_F(SceneParser, RotationIsXThenYThenZAfterScale) {
  json scene = goodScene();
  // Box 1 x 2 x 3: X by 90 makes it 1 x 3 x 2, then Y by 90 makes it 2 x 3 x 1.
  // (Y first would give 3 x 1 x 2.)
  scene["objects"] = json::parse(R"([
    {"primitive": "box", "size": [1, 2, 3], "rotate": [90, 90, 0]},
    {"primitive": "box", "size": [1, 1, 1], "scale": [4, 1, 1], "rotate": [0, 0, 90], "translate": [1, 2, 3]},
    {"primitive": "sphere", "radius": 1, "scale": [3, 1, 1]}
  ])");
  const Scene parsed = loadScene(writeScene("rot.json", scene));
  expectVec(bounds(parsed.objects[0].mesh).size(), {2, 3, 1});
  // Scale stretches x to 4 before Z by 90 turns it into y; translate comes last.
  expectVec(bounds(parsed.objects[1].mesh).size(), {1, 4, 1});
  expectVec(bounds(parsed.objects[1].mesh).centre(), {1, 2, 3});
  const TriMesh& ellipsoid = parsed.objects[2].mesh;
  EXPECT_NEAR(bounds(ellipsoid).size().x, 6.0f, 1e-4f);
  // Normals are recomputed from the stretched surface: unit length and outward.
  for (const auto v : ellipsoid.vertices()) {
    const auto n = ellipsoid.normal(v);
    EXPECT_NEAR(n.norm(), 1.0f, 1e-4f);
    EXPECT_GT(OpenMesh::dot(n, ellipsoid.point(v)), 0.0f);
  }
  // For a stretched sphere the normal at (3 cos t, sin t) is along (cos t / 3, sin t).
  for (const auto v : ellipsoid.vertices()) {
    const auto p = ellipsoid.point(v);
    if (std::abs(p[2]) < 1e-5f && std::abs(p[0]) > 1.0f && std::abs(p[1]) > 0.3f) {
      const auto n = ellipsoid.normal(v);
      EXPECT_NEAR(n[1] / n[0], (p[1]) / (p[0] / 9.0f), 0.25f * std::abs(p[1] / (p[0] / 9.0f)));
    }
  }
}

TEST_F(SceneParser, MeshFitCentresAndScales) {
  write("tet.off", kTetrahedronOff);
  json scene = goodScene();
  scene["objects"] = json::parse(R"([
    {"mesh": "tet.off", "fit": 20, "translate": [0, -2, 10]},
    {"mesh": "tet.off", "fit": 20, "scale": 0.5, "subdivide": 1}
  ])");
  const Scene parsed = loadScene(writeScene("fit.json", scene));
  const Box fitted = bounds(parsed.objects[0].mesh);
  expectVec(fitted.size(), {20, 20, 20});
  expectVec(fitted.centre(), {0, -2, 10});
  EXPECT_EQ(parsed.objects[0].label, "objects[0] (mesh tet.off)");
  // Loop subdivision quadruples the faces before fit, which still sizes the result.
  const TriMesh& smooth = parsed.objects[1].mesh;
  EXPECT_EQ(smooth.n_faces(), 16u);
  EXPECT_NEAR(std::max({bounds(smooth).size().x, bounds(smooth).size().y, bounds(smooth).size().z}),
              10.0f, 1e-3f);
  for (const auto h : smooth.halfedges()) EXPECT_FALSE(smooth.is_boundary(h));
}

TEST_F(SceneParser, SubdividedPrimitiveStaysClosed) {
  json scene = goodScene();
  scene["objects"] = json::parse(R"([{"primitive": "box", "size": [1, 1, 1], "subdivide": 2}])");
  const Scene parsed = loadScene(writeScene("sub.json", scene));
  const TriMesh& mesh = parsed.objects[0].mesh;
  EXPECT_EQ(mesh.n_faces(), 12u * 16u);
  for (const auto h : mesh.halfedges()) EXPECT_FALSE(mesh.is_boundary(h));
}

TEST_F(SceneParser, AssetNamesComeFromTheAssetDirectory) {
  const fs::path assets = dir_ / "assets";
  test::writeFile(assets / "tet.off", kTetrahedronOff);
  const ScopedEnv env("TESTBED_ASSET_DIR", assets.string());
  EXPECT_EQ(assetDirectory(), assets);
  json scene = goodScene();
  scene["objects"] = json::parse(R"([{"mesh": "tet"}])");
  EXPECT_EQ(loadScene(writeScene("asset.json", scene)).objects[0].mesh.n_faces(), 4u);
  scene["objects"] = json::parse(R"([{"mesh": "bunny"}])");
  // Both places looked are named.
  expectError(writeScene("noasset.json", scene), "objects[0].mesh",
              (assets / "bunny").string() + ".{off,obj,ply,stl}");
  expectError(writeScene("noasset.json", scene), "objects[0].mesh", (dir_ / "bunny").string());
}

TEST_F(SceneParser, EmptyAssetVariableFallsBackToTheBuildDefault) {
  const ScopedEnv env("TESTBED_ASSET_DIR", "");
  EXPECT_FALSE(assetDirectory().empty());
#ifdef TESTBED_DEFAULT_ASSET_DIR
  EXPECT_EQ(assetDirectory(), fs::path(TESTBED_DEFAULT_ASSET_DIR));
#endif
}

TEST_F(SceneParser, BrokenMeshNamesSceneKeyAndMeshFile) {
  const fs::path broken = write("broken.off", "");
  json scene = goodScene();
  scene["objects"] = json::array({goodScene()["objects"][0], {{"mesh", "broken.off"}}});
  expectError(writeScene("x.json", scene), "objects[1].mesh", broken.string() + ": file is empty");
  scene["objects"][1]["mesh"] = "missing.off";
  expectError(writeScene("x.json", scene), "objects[1].mesh", "not found");
}

TEST_F(SceneParser, MissingFileAndSyntaxErrors) {
  expectError(dir_ / "missing.json", "", "no such file");
  expectError(write("syntax.json", "{\n  \"name\": \"x\",\n  oops\n}\n"), "",
              "line 3, column 3: JSON syntax error");
  expectError(write("empty.json", ""), "", "JSON syntax error");
  expectError(write("array.json", "[1, 2]"), "", "expected a JSON object at the top level");
}

TEST_F(SceneParser, InfinityFromHugeLiteralIsRejected) {
  std::string text = goodScene().dump();
  text.replace(text.find("500"), 3, "1e999");  // camera.far
  expectError(write("inf.json", text), "camera.far", "not a finite number");
  expectBad([](json& s) { s["camera"]["far"] = 1e300; }, "camera.far", "too large");
  text = goodScene().dump();
  text.replace(text.find("-50"), 3, "-1e999");  // camera.eye[2]
  expectError(write("inf2.json", text), "camera.eye[2]", "not a finite number");
  text = goodScene().dump();
  text.replace(text.find("-8"), 2, "1e999");  // objects[1].translate[1]
  expectError(write("inf3.json", text), "objects[1].translate[1]", "not a finite number");
}

TEST_F(SceneParser, UnknownKeysAreErrorsAtEveryLevel) {
  expectBad([](json& s) { s["colour"] = "red"; }, "colour", "unknown key");
  expectBad([](json& s) { s["camera"]["fov"] = 45; }, "camera.fov", "unknown key");
  expectBad([](json& s) { s["light"]["colour"] = 1; }, "light.colour", "unknown key");
  expectBad([](json& s) { s["objects"][1]["colour"] = 1; }, "objects[1].colour", "unknown key");
  expectBad([](json& s) { s["objects"][0]["fit"] = 3; }, "objects[0].fit", "unknown key");
  expectBad(
      [](json& s) {
        s["light"]["direction"] = {0, -1, 0};
      },
      "light.direction", "unknown key");
  expectBad(
      [](json& s) {
        s["light"] = {
            {"type", "directional"}, {"direction", {0, -1, 0}}, {"extent", 5}, {"fov", 30}};
      },
      "light.fov", "unknown key");
  // A key with a newline is quoted so that the message stays on one line.
  expectBad([](json& s) { s["we\nird"] = 1; }, "[\"we\\nird\"]", "unknown key");
  expectBad([](json& s) { s["comment"] = 5; }, "comment", "expected a string");
}

TEST_F(SceneParser, WrongTypesAndShapes) {
  expectBad([](json& s) { s["objects"][0]["scale"] = "big"; }, "objects[0].scale",
            "expected a positive number or [x, y, z], got \"big\"");
  expectBad(
      [](json& s) {
        s["camera"]["eye"] = {1, 2};
      },
      "camera.eye", "expected [x, y, z], got [1,2]");
  expectBad([](json& s) { s["camera"]["eye"][2] = "z"; }, "camera.eye[2]", "expected a number");
  expectBad([](json& s) { s["camera"]["near"] = true; }, "camera.near",
            "expected a number, got true");
  expectBad([](json& s) { s["camera"] = 3; }, "camera", "expected a JSON object");
  expectBad([](json& s) { s["objects"][0] = 5; }, "objects[0]", "expected a JSON object");
  expectBad([](json& s) { s["name"] = 5; }, "name", "expected a non-empty string");
  expectBad(
      [](json& s) {
        s["objects"][1]["size"] = {60, 40, 1};
      },
      "objects[1].size", "expected [x, z]");
  expectBad([](json& s) { s["objects"][0]["primitive"] = 7; }, "objects[0].primitive",
            "expected a string");
}

TEST_F(SceneParser, OutOfRangeValues) {
  expectBad([](json& s) { s["camera"]["fov_y"] = 180; }, "camera.fov_y",
            "must be > 0 and < 180, got 180");
  expectBad([](json& s) { s["light"]["fov"] = -5; }, "light.fov", "must be > 0");
  expectBad([](json& s) { s["camera"]["far"] = 0.1; }, "camera.far", "must be greater than near");
  expectBad([](json& s) { s["light"]["radius"] = -1; }, "light.radius", "must be >= 0");
  expectBad([](json& s) { s["objects"][0]["scale"] = 0; }, "objects[0].scale", "must be > 0");
  expectBad([](json& s) { s["camera"]["near"] = 1e-50; }, "camera.near",
            "must be > 0");  // 0 as float
  expectBad(
      [](json& s) {
        s["objects"][0]["scale"] = {1, 1, -1};
      },
      "objects[0].scale[2]", "must be > 0");
  expectBad([](json& s) { s["objects"][0]["size"][1] = -2; }, "objects[0].size[1]", "must be > 0");
  expectBad([](json& s) { s["objects"][0]["subdivide"] = 5; }, "objects[0].subdivide",
            "must be an integer in [0, 4], got 5");
  expectBad([](json& s) { s["objects"][0]["subdivide"] = 2.5; }, "objects[0].subdivide",
            "expected an integer");
  expectBad([](json& s) { s["objects"][1]["segments"] = 0; }, "objects[1].segments", "[1, 1024]");
  expectBad(
      [](json& s) {
        s["objects"][0] = {{"primitive", "torus"}, {"major", 1}, {"minor", 2}};
      },
      "objects[0].minor", "must be smaller than major");
  expectBad(
      [](json& s) {
        s["objects"][0] = {{"primitive", "fence"}, {"width", 1},       {"height", 1},
                           {"bars", 1.5},          {"bar_width", 0.1}, {"bar_depth", 0.1}};
      },
      "objects[0].bars", "expected an integer");
  expectBad(
      [](json& s) {
        s["objects"][0]["scale"] = 1e30;
        s["objects"][0]["size"] = {1e30, 1, 1};
      },
      "objects[0]", "not finite");
}

TEST_F(SceneParser, CameraAndLightGeometry) {
  expectBad([](json& s) { s["camera"]["target"] = s["camera"]["eye"]; }, "camera.target",
            "must differ");
  expectBad([](json& s) { s["camera"]["up"] = {0, 25, -40}; }, "camera.up", "not parallel");
  expectBad([](json& s) { s["camera"]["up"] = {0, 0, 0}; }, "camera.up", "non-zero");
  expectBad([](json& s) { s["camera"].erase("eye"); }, "camera.eye", "missing required key");
  expectBad([](json& s) { s.erase("light"); }, "light", "missing required key");
  expectBad([](json& s) { s["light"].erase("type"); }, "light.type", "missing required key");
  expectBad([](json& s) { s["light"]["type"] = "point"; }, "light.type",
            "expected \"spot\" or \"directional\"");
  expectBad(
      [](json& s) {
        s["light"] = {{"type", "directional"}, {"direction", {0, 0, 0}}, {"extent", 5}};
      },
      "light.direction", "non-zero");
  expectBad(
      [](json& s) {
        s["light"] = {{"type", "directional"}, {"direction", {0, -1, 0}}, {"fit", false}};
      },
      "light.extent", "missing required key");
}

TEST_F(SceneParser, ObjectSourceErrors) {
  expectBad([](json& s) { s["objects"][0]["mesh"] = "bunny"; }, "objects[0]",
            "both \"mesh\" and \"primitive\"");
  expectBad([](json& s) { s["objects"][0].erase("primitive"); }, "objects[0]",
            "needs either \"mesh\" or \"primitive\"");
  expectBad([](json& s) { s["objects"] = json::array(); }, "objects", "non-empty array");
  expectBad([](json& s) { s["objects"] = json::object(); }, "objects", "non-empty array");
  expectBad([](json& s) { s["objects"][0]["primitive"] = "cone"; }, "objects[0].primitive",
            "unknown primitive \"cone\"");
  expectBad(
      [](json& s) {
        s["objects"][0] = {{"mesh", ""}};
      },
      "objects[0].mesh", "expected a mesh name");
}

TEST_F(SceneParser, TriangleLimit) {
  // 2 * 1024^2 triangles times 4^3 for three Loop levels: refused before anything is built.
  expectBad(
      [](json& s) {
        s["objects"][1]["segments"] = 1024;
        s["objects"][1]["subdivide"] = 3;
      },
      "objects[1]", "the scene would have 134217740 triangles, more than the limit of 20000000");
  expectBad(
      [](json& s) {
        s["objects"][0] = {{"primitive", "sphere"},
                           {"radius", 1},
                           {"segments", 1024},
                           {"rings", 1024},
                           {"subdivide", 4}};
      },
      "objects[0]", "more than the limit");
}

}  // namespace
}  // namespace testbed
