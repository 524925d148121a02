// The corpus generator on meshes written here, with a stand-in for the check render:
// deterministic text, scenes that do not depend on the count, every scene valid for the
// parser, unusable meshes skipped with a reason, rejected draws drawn again, and the
// texel estimate pinned on cases worked by hand.
#include <gtest/gtest.h>

#include <set>

#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/scene/corpus.h"
#include "tests/cli_helpers.h"
#include "tests/mesh_fixtures.h"

namespace testbed {
namespace {

// A closed lumpy sphere (252 triangles), a closed tetrahedron (4: a box, not a shape), the
// sphere again under a folder named invalid, the sphere shrunk to 1e-40 (its fit to 22
// units overflows float), a flat square and a file that is no mesh.
void writeMeshes(const test::TempDir& dir) {
  test::writeFile(dir / "meshes/lumpy.off", test::lumpySphereOff());
  test::writeFile(dir / "meshes/tetra.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  test::writeFile(dir / "meshes/invalid/lumpy-again.off", test::lumpySphereOff(2.0));
  test::writeFile(dir / "meshes/tiny.off", test::lumpySphereOff(1e-40));
  // Flat, with enough triangles (a 15 × 15 grid, 392) that flatness is its fault.
  std::string sheet = "OFF\n225 392 0\n";
  for (int z = 0; z < 15; ++z)
    for (int x = 0; x < 15; ++x) sheet += std::to_string(x) + " 0 " + std::to_string(z) + "\n";
  for (int z = 0; z < 14; ++z)
    for (int x = 0; x < 14; ++x) {
      const int i = 15 * z + x;
      sheet += "3 " + std::to_string(i) + " " + std::to_string(i + 15) + " " + std::to_string(i + 1) + "\n";
      sheet += "3 " + std::to_string(i + 1) + " " + std::to_string(i + 15) + " " + std::to_string(i + 16) + "\n";
    }
  test::writeFile(dir / "meshes/sub/sheet.off", sheet);
  test::writeFile(dir / "meshes/broken.obj", "this is not a mesh\n");
}

// Counts a check render of an admissible scene could give.
GroundTruthCounts admissible() { return {1000, 2 * kCorpusMinBoundaryPixels, 600, 400}; }

CorpusOptions optionsFor(const test::TempDir& dir, std::uint64_t seed, int count) {
  CorpusOptions options;
  options.seed = seed;
  options.count = count;
  options.meshFolders = {dir / "meshes"};
  options.render = [](const Scene&) { return admissible(); };
  return options;
}

std::string why(const nlohmann::json& skipped, const std::string& mesh) {
  for (const auto& entry : skipped)
    if (entry["mesh"].get<std::string>().ends_with(mesh)) return entry["why"];
  return "(not skipped)";
}

TEST(Corpus, SameSeedSameTextOtherSeedOtherText) {
  test::TempDir dir;
  writeMeshes(dir);
  const Corpus a = generateCorpus(optionsFor(dir, 7, 6)), b = generateCorpus(optionsFor(dir, 7, 6));
  const Corpus c = generateCorpus(optionsFor(dir, 8, 6));
  ASSERT_EQ(a.scenes.size(), 6u);
  EXPECT_EQ(a.manifest, b.manifest);
  for (std::size_t i = 0; i < a.scenes.size(); ++i) {
    EXPECT_EQ(a.scenes[i].name, b.scenes[i].name);
    EXPECT_EQ(a.scenes[i].text, b.scenes[i].text);
    EXPECT_NE(a.scenes[i].text, c.scenes[i].text);
  }
}

TEST(Corpus, SceneIDoesNotDependOnTheCount) {
  test::TempDir dir;
  writeMeshes(dir);
  const Corpus few = generateCorpus(optionsFor(dir, 3, 2)), many = generateCorpus(optionsFor(dir, 3, 9));
  EXPECT_EQ(few.scenes[0].text, many.scenes[0].text);
  EXPECT_EQ(few.scenes[1].text, many.scenes[1].text);
}

TEST(Corpus, EveryScenePassesTheParserAndUnusableMeshesAreListed) {
  test::TempDir dir;
  writeMeshes(dir);
  const Corpus corpus = generateCorpus(optionsFor(dir, 11, 40));
  for (const auto& scene : corpus.scenes) {
    SCOPED_TRACE(scene.name);
    const Scene parsed = parseScene(nlohmann::json::parse(scene.text), dir / scene.name);
    EXPECT_GE(parsed.objects.size(), 2u);
    EXPECT_GT(parsed.light.radius, 0.0f);
  }
  const auto manifest = nlohmann::json::parse(corpus.manifest);
  ASSERT_EQ(manifest["meshes"].size(), 1u);
  EXPECT_NE(manifest["meshes"][0]["mesh"].get<std::string>().find("lumpy.off"), std::string::npos);
  const auto& skipped = manifest["skipped"];
  EXPECT_EQ(skipped.size(), 5u) << skipped.dump(2);
  EXPECT_NE(why(skipped, "broken.obj").find("broken.obj:"), std::string::npos) << why(skipped, "broken.obj");
  EXPECT_NE(why(skipped, "sheet.off").find("flat"), std::string::npos);
  EXPECT_NE(why(skipped, "tetra.off").find("only 4 triangles (fewer than 200"), std::string::npos);
  EXPECT_NE(why(skipped, "invalid/lumpy-again.off").find("under a folder named invalid"), std::string::npos);
  EXPECT_NE(why(skipped, "tiny.off").find("transformed coordinates are not finite"), std::string::npos)
      << why(skipped, "tiny.off");
  // Elevations within 3°–85°, both kinds of light and camera among 40 scenes, and every
  // close-up at least at the wanted 4 pixels per texel (the estimate, taken again).
  std::set<std::string> lights, cameras;
  for (const auto& s : manifest["scenes"]) {
    EXPECT_GE(s["elevation_deg"].get<double>(), 3.0);
    EXPECT_LE(s["elevation_deg"].get<double>(), 85.0);
    lights.insert(s["light"].get<std::string>());
    cameras.insert(s["camera"].get<std::string>());
    if (s["camera"] == "close-up") {
      EXPECT_GE(s["pixels_per_texel"].get<double>(), 3.99) << s.dump();
    }
  }
  EXPECT_EQ(lights.size(), 2u);
  EXPECT_EQ(cameras.size(), 2u);
}

// A draw the check render refuses, or whose ground truth shows too little, is drawn again
// from its own stream; the manifest keeps each rejection with its reason and the counts
// of the draw it kept.
TEST(Corpus, RejectedDrawsAreDrawnAgainAndListed) {
  test::TempDir dir;
  writeMeshes(dir);
  CorpusOptions options = optionsFor(dir, 5, 3);
  int calls = 0;
  options.render = [&calls](const Scene&) -> GroundTruthCounts {
    switch (calls++ % 3) {
      case 0: throw InputError("the renderer refuses it");
      case 1: return {1000, kCorpusMinBoundaryPixels - 1, 500, 500};
      default: return admissible();
    }
  };
  const Corpus corpus = generateCorpus(options);
  const auto manifest = nlohmann::json::parse(corpus.manifest);
  for (const auto& scene : manifest["scenes"]) {
    SCOPED_TRACE(scene.dump());
    EXPECT_EQ(scene["draw"], 2);
    ASSERT_EQ(scene["rejected_draws"].size(), 2u);
    EXPECT_EQ(scene["rejected_draws"][0]["why"], "the renderer refuses it");
    EXPECT_NE(scene["rejected_draws"][1]["why"].get<std::string>().find("39 boundary pixels"), std::string::npos);
    EXPECT_EQ(scene["check"]["boundary_px"], admissible().boundaryPixels);
  }
  // The kept draw is a new scene, not draw 0 again, and says which draw it is.
  const Corpus first = generateCorpus(optionsFor(dir, 5, 3));
  EXPECT_NE(first.scenes[1].text, corpus.scenes[1].text);
  EXPECT_NE(corpus.scenes[1].text.find("(scene 1, draw 2)"), std::string::npos);
  // Too few lit or shadowed receivers is a rejection too; a scene no draw admits is an
  // InputError.
  options.render = [](const Scene&) { return GroundTruthCounts{1000, 100, 995, 5}; };
  try {
    generateCorpus(options);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("none of 32 draws"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("995 lit and 5 shadowed of 1000"), std::string::npos) << error.what();
  }
}

TEST(Corpus, NoUsableMeshIsAnInputError) {
  test::TempDir dir;
  test::writeFile(dir / "meshes/broken.obj", "not a mesh\n");
  try {
    generateCorpus(optionsFor(dir, 1, 1));
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("--meshes: no usable"), std::string::npos) << error.what();
  }
}

// Worked by hand: a directional light straight down with extent 51.2 gives texels of
// 0.1 × 0.1 on the floor; a camera 10 above looking down with fov 90° at 720 rows gives
// pixels of 20/720 on a side: (0.01) / (20/720)² = 12.96 pixels per texel.
TEST(Corpus, PixelsPerTexelOnAWorkedCase) {
  LightDesc sun;
  sun.type = LightType::Directional;
  sun.direction = {0, -1, 0};
  sun.extent = 51.2f;
  CameraDesc camera;
  camera.eye = {0, 10, 0};
  camera.fovYDegrees = 90;
  EXPECT_NEAR(pixelsPerTexel(sun, camera, {1280, 720}, 1024, {0, 0, 0}), 12.96, 1e-4);
  // A sun at 30° elevation stretches the texel to twice its area; a spot light 100 above
  // with fov 90° has texels of 200/1024 on a side.
  sun.direction = {std::cos(glm::radians(30.0f)), -0.5f, 0};
  EXPECT_NEAR(pixelsPerTexel(sun, camera, {1280, 720}, 1024, {0, 0, 0}), 25.92, 1e-3);
  LightDesc spot;
  spot.eye = {0, 100, 0};
  spot.fovDegrees = 90;
  const double texel = 200.0 / 1024, pixel = 20.0 / 720;
  EXPECT_NEAR(pixelsPerTexel(spot, camera, {1280, 720}, 1024, {0, 0, 0}), texel * texel / (pixel * pixel), 1e-3);
}

}  // namespace
}  // namespace testbed
