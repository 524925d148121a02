#include <OpenMesh/Core/IO/MeshIO.hh>  // must precede the mesh type header

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/scene/animation.h"

namespace testbed {
namespace {

using nlohmann::json;

void expectVec(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-5f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

glm::vec3 centre(const TriMesh& mesh) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto v : mesh.vertices()) {
    const auto p = mesh.point(v);
    lo = glm::min(lo, glm::vec3(p[0], p[1], p[2]));
    hi = glm::max(hi, glm::vec3(p[0], p[1], p[2]));
  }
  return (lo + hi) * 0.5f;
}

// A box over a floor under a directional light, with an animation of 21 frames.
json animatedScene() {
  return json::parse(R"({
    "camera": {"eye": [0, 10, -20], "target": [0, 0, 0]},
    "light": {"type": "directional", "direction": [1, 0, 0], "extent": 20},
    "objects": [
      {"primitive": "box", "size": [2, 2, 2], "translate": [0, 3, 0]},
      {"primitive": "plane", "size": [30, 30]}
    ],
    "animation": {
      "frames": 21, "fps": 24,
      "camera": [{"frame": 4, "eye": [0, 10, -20]}, {"frame": 14, "eye": [0, 20, -40]}],
      "light": [{"frame": 0, "direction": [1, 0, 0]}, {"frame": 20, "direction": [0, -1, 0]}],
      "objects": [{"object": 0, "keys": [{"frame": 0, "translate": [0, 3, 0], "rotate": [0, 0, 0]},
                                          {"frame": 10, "translate": [10, 3, 0], "rotate": [0, 90, 0]}]}]
    }
  })");
}

Scene parse(const json& document) { return parseScene(document, "anim.json"); }

TEST(Animation, TracksInterpolateLinearlyAndHoldOutsideTheirKeys) {
  Track<float> track{{{2, 10.0f}, {6, 30.0f}}};
  EXPECT_EQ(valueAt(track, 0, -1.0f), 10.0f);   // before the first key
  EXPECT_EQ(valueAt(track, 4, -1.0f), 20.0f);   // midway
  EXPECT_EQ(valueAt(track, 5, -1.0f), 25.0f);
  EXPECT_EQ(valueAt(track, 99, -1.0f), 30.0f);  // after the last
  EXPECT_EQ(valueAt(Track<float>{}, 3, -1.0f), -1.0f);  // no keys: the static value
  Track<glm::vec3> points{{{0, glm::vec3(0, 0, 0)}, {10, glm::vec3(10, -20, 4)}}};
  expectVec(valueAt(points, 3, glm::vec3(0)), {3, -6, 1.2f});
}

TEST(Animation, DirectionsFollowTheGreatCircle) {
  Track<glm::vec3> track{{{0, glm::vec3(1, 0, 0)}, {10, glm::vec3(0, 1, 0)}}};
  const float half = std::sqrt(0.5f);
  expectVec(directionAt(track, 5, glm::vec3(0)), {half, half, 0});
  // A fifth of the way along a 90° arc is 18°, not the chord's point.
  const float a = glm::radians(18.0f);
  expectVec(directionAt(track, 2, glm::vec3(0)), {std::cos(a), std::sin(a), 0});
  expectVec(directionAt(track, 20, glm::vec3(0)), {0, 1, 0});
}

// Two keys of one direction hold it at every frame between them (slerp alone divides by
// the sine of a zero angle), and keys a hair apart still give unit vectors on the arc.
TEST(Animation, EqualDirectionKeysHoldTheDirection) {
  const glm::vec3 d = glm::normalize(glm::vec3(0.3946f, -0.8660f, 0.3069f));
  Track<glm::vec3> same{{{0, d}, {47, d}}};
  for (int frame : {0, 1, 23, 46, 47}) expectVec(directionAt(same, frame, glm::vec3(0)), d, 1e-7f);
  const glm::vec3 near = glm::normalize(d + glm::vec3(1e-4f, 0, 0));
  Track<glm::vec3> close{{{0, d}, {10, near}}};
  const glm::vec3 mid = directionAt(close, 5, glm::vec3(0));
  EXPECT_NEAR(glm::length(mid), 1.0f, 1e-6f);
  expectVec(mid, glm::normalize(d + near), 1e-6f);
}

TEST(Animation, UnitDirectionNeitherOverflowsNorUnderflows) {
  const float half = std::sqrt(0.5f);
  expectVec(*unitDirection({1e38f, -1e38f, 0}), {half, -half, 0});
  expectVec(*unitDirection({3e-39f, 0, -3e-39f}), {half, 0, -half});  // denormal components
  expectVec(*unitDirection({0, -5, 0}), {0, -1, 0});
  EXPECT_FALSE(unitDirection({0, 0, 0}));
  EXPECT_FALSE(unitDirection({std::numeric_limits<float>::infinity(), 0, 0}));
  EXPECT_FALSE(unitDirection({std::numeric_limits<float>::quiet_NaN(), 1, 0}));
}

// A whole scene: keys of the same direction, or of a direction with huge components, play
// every frame with the direction the keys give.
TEST(Animation, EqualOrHugeDirectionKeysPlayEveryFrame) {
  for (const json& second : {json{1, 0, 0}, json{1e38, 0, 0}, json{2e-40, 0, 0}}) {
    json document = animatedScene();
    document["animation"]["light"][1]["direction"] = second;
    Scene scene = parse(document);
    for (int frame = 0; frame <= 20; ++frame) {
      applyFrame(scene, frame);
      expectVec(scene.light.direction, {1, 0, 0}, 1e-6f);
    }
  }
}

TEST(Animation, SceneIsItsFirstFrameAndApplyFrameMovesWhatIsKeyed) {
  Scene scene = parse(animatedScene());
  ASSERT_TRUE(scene.animation);
  EXPECT_EQ(scene.animation->frames, 21);
  EXPECT_EQ(scene.animation->fps, 24);
  expectVec(scene.camera.eye, {0, 10, -20});
  expectVec(centre(scene.objects[0].mesh), {0, 3, 0});

  const FrameChange five = applyFrame(scene, 5);
  EXPECT_TRUE(five.camera);
  EXPECT_TRUE(five.light);
  ASSERT_EQ(five.objects.size(), 1u);
  EXPECT_EQ(five.objects[0], 0u);
  expectVec(scene.camera.eye, {0, 11, -22});  // a tenth of the way from frame 4 to 14
  const float a = glm::radians(22.5f);        // a quarter of the 90° from +x to −y
  expectVec(scene.light.direction, {std::cos(a), -std::sin(a), 0});
  expectVec(centre(scene.objects[0].mesh), {5, 3, 0}, 1e-4f);
  EXPECT_EQ(scene.objects[0].pose.rotateDegrees.y, 45.0f);

  // After the object's last key it holds: only the camera and light move on.
  applyFrame(scene, 12);
  const FrameChange later = applyFrame(scene, 13);
  EXPECT_TRUE(later.camera);
  EXPECT_TRUE(later.objects.empty());
  expectVec(centre(scene.objects[0].mesh), {10, 3, 0}, 1e-4f);
  // After the camera's last key it holds too.
  applyFrame(scene, 14);
  const FrameChange held = applyFrame(scene, 15);
  EXPECT_FALSE(held.camera);
  EXPECT_TRUE(held.light);
  // Back to frame 0: the box is where the file put it, the revision moved on.
  const auto revision = scene.geometryRevision;
  applyFrame(scene, 0);
  expectVec(centre(scene.objects[0].mesh), {0, 3, 0}, 1e-4f);
  EXPECT_GT(scene.geometryRevision, revision);
  EXPECT_THROW(applyFrame(scene, 21), InputError);
}

TEST(Animation, AStillSceneHasOnlyFrameZeroAndIsUnchanged) {
  json document = animatedScene();
  document.erase("animation");
  Scene scene = parse(document);
  EXPECT_FALSE(scene.animation);
  EXPECT_FALSE(scene.objects[0].local);  // nothing kept that a still scene does not need
  EXPECT_FALSE(applyFrame(scene, 0).any());
  EXPECT_THROW(applyFrame(scene, 1), InputError);
}

TEST(Animation, AnimatedObjectIsPlacedExactlyAsAStillOne) {
  // Same file, animation without object keys vs. with a key that repeats the placement.
  json still = animatedScene();
  still.erase("animation");
  json moving = animatedScene();
  moving["animation"]["objects"][0]["keys"] = json::parse(R"([{"frame": 0, "translate": [0, 3, 0]}])");
  const Scene a = parse(still), b = parse(moving);
  ASSERT_EQ(a.objects[0].mesh.n_vertices(), b.objects[0].mesh.n_vertices());
  for (const auto v : a.objects[0].mesh.vertices())
    EXPECT_EQ(a.objects[0].mesh.point(v), b.objects[0].mesh.point(v));
}

// Every refusal: one line "<file>: <key path>: <problem>".
void expectRefused(const std::function<void(json&)>& edit, const std::string& key, const std::string& problem) {
  json document = animatedScene();
  edit(document);
  try {
    parse(document);
    ADD_FAILURE() << "expected an InputError at " << key;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("anim.json: " + key + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(problem), std::string::npos) << message << "\nexpected: " << problem;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(AnimationHostile, RefusesBadBlocksNamingTheKeyPath) {
  expectRefused([](json& d) { d["animation"]["frames"] = 0; }, "animation.frames", "[1, 100000]");
  expectRefused([](json& d) { d["animation"]["frames"] = 2.5; }, "animation.frames", "integer");
  expectRefused([](json& d) { d["animation"].erase("frames"); }, "animation.frames", "missing required key");
  expectRefused([](json& d) { d["animation"]["fps"] = 0; }, "animation.fps", "[1, 240]");
  expectRefused([](json& d) { d["animation"]["speed"] = 2; }, "animation.speed", "unknown key");
  expectRefused([](json& d) { d["animation"] = 3; }, "animation", "expected a JSON object");
  // Unsorted, repeated and out-of-range keys.
  expectRefused([](json& d) { d["animation"]["camera"][1]["frame"] = 2; }, "animation.camera[1].frame",
                "after the previous key's frame 4");
  expectRefused([](json& d) { d["animation"]["camera"][1]["frame"] = 4; }, "animation.camera[1].frame",
                "each frame once");
  expectRefused([](json& d) { d["animation"]["light"][1]["frame"] = 21; }, "animation.light[1].frame", "[0, 20]");
  expectRefused([](json& d) { d["animation"]["light"][0]["frame"] = -1; }, "animation.light[0].frame", "[0, 20]");
  expectRefused([](json& d) { d["animation"]["camera"] = json::array(); }, "animation.camera", "non-empty array");
  expectRefused([](json& d) { d["animation"]["camera"][0].erase("eye"); }, "animation.camera[0]",
                "no value besides");
  expectRefused([](json& d) { d["animation"]["camera"][0]["up"] = {0, 1, 0}; }, "animation.camera[0].up",
                "unknown key");
  // Object index out of range, twice, unknown keys in a key.
  expectRefused([](json& d) { d["animation"]["objects"][0]["object"] = 2; }, "animation.objects[0].object",
                "[0, 1]");
  expectRefused([](json& d) { d["animation"]["objects"].push_back(d["animation"]["objects"][0]); },
                "animation.objects[1].object", "animated twice");
  expectRefused([](json& d) { d["animation"]["objects"][0]["keys"][0]["spin"] = 1; },
                "animation.objects[0].keys[0].spin", "unknown key");
  expectRefused([](json& d) { d["animation"]["objects"][0]["keys"][0]["scale"] = -1; },
                "animation.objects[0].keys[0].scale", "must be > 0");
  // A field the light type does not have.
  expectRefused([](json& d) { d["animation"]["light"][0]["eye"] = {0, 1, 0}; }, "animation.light[0].eye",
                "a directional light has no eye");
  expectRefused(
      [](json& d) {
        d["light"] = {{"type", "spot"}, {"eye", {0, 20, 0}}, {"target", {0, 0, 0}}};
        d["animation"]["light"] = json::parse(R"([{"frame": 0, "direction": [0, -1, 0]}])");
      },
      "animation.light[0].direction", "a spot light has no direction");
  // NaN and infinity.
  expectRefused([](json& d) { d["animation"]["camera"][0]["eye"][1] = std::numeric_limits<double>::quiet_NaN(); },
                "animation.camera[0].eye[1]", "not a finite number");
  expectRefused([](json& d) { d["animation"]["light"][1]["direction"][0] = std::numeric_limits<double>::infinity(); },
                "animation.light[1].direction[0]", "not a finite number");
  // Values that are valid one by one but not together.
  expectRefused([](json& d) { d["animation"]["light"][1]["direction"] = {-1, 0, 0}; },
                "animation.light[1].direction", "opposite");
  expectRefused([](json& d) { d["animation"]["light"][1]["direction"] = {0, 0, 0}; },
                "animation.light[1].direction", "non-zero vector");
  expectRefused([](json& d) { d["light"]["direction"] = {0, 0, 0}; }, "light.direction", "non-zero vector");
  expectRefused([](json& d) { d["animation"]["camera"][1]["eye"] = {0, 0, 0}; }, "animation.camera.target",
                "(at frame 14)");
  expectRefused(
      [](json& d) {
        d["animation"]["objects"][0]["keys"][1]["translate"] = {3e38, 0, 0};
        d["animation"]["objects"][0]["keys"][1]["scale"] = 3e38;
      },
                "animation.objects[0]", "not finite");
  // Finite at both keys, but a box 2e37 long swung through 180° about Y stands along Z
  // halfway, where 1.6e38 + 2e38 overflows: found by fuzz/animation_fuzz.cpp, refused
  // before the first frame instead of failing at frame 1.
  expectRefused(
      [](json& d) {
        d["objects"][0] = json::parse(R"({"primitive": "box", "size": [16, 0.6, 3]})");
        d["animation"]["objects"][0]["keys"] = json::parse(
            R"([{"frame": 0, "scale": 2e37, "rotate": [0, 0, 0], "translate": [0, 0, 2e38]},
                {"frame": 2, "rotate": [0, 180, 0]}])");
      },
      "animation.objects[0]", "between keys");
}

// The bound that refuses the case above lets every scene of sensible size through: a
// unit box swung through 180° while it grows a thousandfold and moves 1e6 away.
TEST(Animation, LargeButSensiblePlacementsPlayEveryFrame) {
  json d = animatedScene();
  d["animation"]["objects"][0]["keys"] = json::parse(
      R"([{"frame": 0, "scale": 1, "rotate": [0, 0, 0]},
          {"frame": 20, "scale": 1000, "rotate": [0, 180, 0], "translate": [1e6, 0, 0]}])");
  Scene scene = parse(d);
  for (int frame = 0; frame < 21; ++frame) EXPECT_NO_THROW(applyFrame(scene, frame)) << frame;
  expectVec(centre(scene.objects[0].mesh), {1e6f, 0, 0}, 1.0f);
}

}  // namespace
}  // namespace testbed
