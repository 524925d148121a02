#include "testbed/viewer/scene_writer.h"

#include <unistd.h>

#include <fstream>

#include <gtest/gtest.h>

#include "testbed/core/error.h"
#include "testbed/viewer/navigation.h"
#include "tests/cli_helpers.h"

namespace testbed::viewer {
namespace {

namespace fs = std::filesystem;

class ViewerSceneWriter : public ::testing::Test {
 protected:
  void SetUp() override {
    test::writeFile(dir_ / "scenes" / "meshes" / "tet.off",
                    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    test::writeFile(dir_ / "scenes" / "s.json", R"({
  "name": "writer", "comment": "kept",
  "camera": {"eye": [0, 10, -30], "target": [0, 0, 0], "fov_y": 40},
  "light": {"type": "spot", "eye": [0, 40, 10], "target": [0, 0, 0], "near": 5, "far": 90},
  "objects": [{"mesh": "meshes/tet.off", "fit": 4}, {"primitive": "plane", "size": [20, 20]}]
})");
  }
  test::TempDir dir_{"testbed-scene-writer"};
};

// What the button writes loads back, through the CLI's parser, with the moved camera and
// light exactly and everything else as it was, even from another folder.
TEST_F(ViewerSceneWriter, SavedSceneLoadsBackWithTheMovedView) {
  Scene scene = loadScene(dir_ / "scenes" / "s.json");
  orbit(scene.camera, 33, 12);
  zoom(scene.camera, 0.7f);
  orbitLight(scene.light, -20, 5);
  const fs::path saved = dir_ / "elsewhere" / "deeper" / "moved.json";
  saveSceneWithView(scene, saved);
  const Scene back = loadScene(saved);
  EXPECT_EQ(back.camera.eye, scene.camera.eye);
  EXPECT_EQ(back.camera.target, scene.camera.target);
  EXPECT_EQ(back.camera.fovYDegrees, 40.0f);
  EXPECT_EQ(back.light.eye, scene.light.eye);
  EXPECT_EQ(back.light.nearPlane, 5.0f);
  EXPECT_EQ(back.name, "writer");
  ASSERT_EQ(back.objects.size(), 2u);
  EXPECT_EQ(back.objects[0].mesh.n_faces(), scene.objects[0].mesh.n_faces());
  std::ifstream in(saved);
  const auto document = nlohmann::ordered_json::parse(in);
  EXPECT_EQ(document.begin().key(), "name");  // the file's order, not sorted
  EXPECT_EQ(document["comment"], "kept");
  EXPECT_EQ(document["objects"][0]["mesh"], "../../scenes/meshes/tet.off");
}

TEST_F(ViewerSceneWriter, DirectionalLightKeepsItsType) {
  LightDesc sun;
  sun.type = LightType::Directional;
  sun.target = {1, 2, 3};
  sun.direction = {0, 0, -1};
  const auto document = sceneWithView(
      nlohmann::ordered_json::parse(R"({"light": {"type": "directional", "direction": [0, -1, 0], "extent": 9}, "objects": []})"),
      "a/s.json", "a/t.json", CameraDesc{}, sun);
  EXPECT_EQ(document["light"]["type"], "directional");
  EXPECT_EQ(document["light"]["direction"], nlohmann::ordered_json::array({0.0, 0.0, -1.0}));
  EXPECT_EQ(document["light"]["target"], nlohmann::ordered_json::array({1.0, 2.0, 3.0}));
  EXPECT_FALSE(document["light"].contains("eye"));
}

}  // namespace
}  // namespace testbed::viewer
