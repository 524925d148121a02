// libFuzzer harness for a scene's animation block (testbed/scene/scene_parser.cpp "The
// animation block", testbed/scene/animation.cpp): the input is the block's JSON, put into a
// fixed scene of primitives (a spot light; a first byte 'D' makes it directional), parsed
// as `--scene` parses it, then played as `render` plays it. Any input must end in an
// InputError from the parser, or in a scene whose every frame applies: finite camera,
// light and meshes, never an error in the middle of a sequence.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/scene/animation.h"
#include "testbed/scene/scene.h"

namespace {

const char* const kSpotLight =
    R"({"type": "spot", "eye": [6, 40, 12], "target": [0, 0, 0], "fov": 60, "near": 1, "far": 1000})";
const char* const kDirectionalLight = R"({"type": "directional", "direction": [-0.3, -1, 0.2], "extent": 40})";

std::string sceneAround(const std::string& light, const std::string& animation) {
  return R"({"name": "fuzz", "camera": {"eye": [0, 30, -40], "target": [0, 0, 0], "fov_y": 45, "near": 1, "far": 500},
             "light": )" + light + R"(, "objects": [{"primitive": "plane", "size": [60, 60]},
             {"primitive": "box", "size": [16, 0.6, 3], "translate": [0, 9, 0]}], "animation": )" + animation + "}";
}

bool finite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The frames worth playing: the ends, every key, the middle of every two keys (where
// interpolation is farthest from them) and a few spread over the sequence.
std::set<int> framesToPlay(const testbed::Animation& a) {
  std::set<int> keys = {0, a.frames - 1};
  auto addKeys = [&](const auto& track) {
    for (const auto& key : track.keys) keys.insert(key.first);
  };
  addKeys(a.cameraEye), addKeys(a.cameraTarget), addKeys(a.cameraFovY), addKeys(a.lightEye);
  addKeys(a.lightTarget), addKeys(a.lightDirection), addKeys(a.lightFov), addKeys(a.lightExtent);
  for (const auto& o : a.objects) addKeys(o.scale), addKeys(o.rotate), addKeys(o.translate);
  std::set<int> frames = keys;
  for (auto it = keys.begin(); std::next(it) != keys.end(); ++it) frames.insert((*it + *std::next(it)) / 2);
  for (int i = 0; i < 16; ++i) frames.insert(int(std::int64_t(a.frames - 1) * i / 15));
  return frames;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool directional = size > 0 && data[0] == 'D';
  const std::string block(reinterpret_cast<const char*>(data) + (directional ? 1 : 0), size - (directional ? 1 : 0));
  const std::filesystem::path file = "/nonexistent-testbed-fuzz/animated.json";
  testbed::Scene scene;
  try {
    const std::string text = sceneAround(directional ? kDirectionalLight : kSpotLight, block);
    scene = testbed::parseScene(testbed::parseJsonInput(text, file), file);
  } catch (const testbed::InputError&) {
    return 0;
  }
  if (!scene.animation) return 0;
  // What the parser accepted must play: an error here would stop a sequence half-rendered.
  for (const int frame : framesToPlay(*scene.animation)) {
    testbed::applyFrame(scene, frame);
    if (!finite(scene.camera.eye) || !finite(scene.camera.target) || !std::isfinite(scene.camera.fovYDegrees))
      std::abort();
    if (!finite(scene.light.eye) || !finite(scene.light.target) || !finite(scene.light.direction)) std::abort();
    for (const auto& object : scene.objects)
      for (const auto v : object.mesh.vertices()) {
        const auto& p = object.mesh.point(v);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) std::abort();
      }
  }
  return 0;
}
