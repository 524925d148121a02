#include "testbed/scene/animation_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/scene/scene_values.h"

namespace testbed::scene_file {
namespace {

// An animation's frames are rendered one by one; this bounds a typo, not a real sequence.
constexpr int kMaxAnimationFrames = 100'000;

// Reads a list of keys, each with a "frame" in [0, frames − 1], strictly after the
// previous key's; `fields` reads the rest of a key and returns how many values it gave.
template <class Fields>
void keyList(const JsonField& list, int frames, Fields fields) {
  const std::size_t n = nonEmptyArray(list, "a non-empty array of keys");
  int previous = -1;
  for (std::size_t i = 0; i < n; ++i) {
    const JsonField key = list[i].object();
    const JsonField frameField = key["frame"];
    const int frame = frameField.integer(0, frames - 1);
    if (frame <= previous)
      frameField.fail("must be after the previous key's frame " + std::to_string(previous) + ", got " +
                      std::to_string(frame) + " (keys sorted, each frame once)");
    previous = frame;
    if (fields(key, frame) == 0) key.fail("gives no value besides \"frame\"");
  }
}

template <class T>
int addKey(Track<T>& track, int frame, const T& value) {
  track.keys.emplace_back(frame, value);
  return 1;
}

void cameraKeys(const JsonField& list, Animation& a) {
  keyList(list, a.frames, [&](const JsonField& k, int frame) {
    allowKeys(k, {"frame", "eye", "target", "fov_y"});
    int n = 0;
    if (const auto v = k.find("eye")) n += addKey(a.cameraEye, frame, vec3(*v));
    if (const auto v = k.find("target")) n += addKey(a.cameraTarget, frame, vec3(*v));
    if (const auto v = k.find("fov_y")) n += addKey(a.cameraFovY, frame, bounded(*v, 0.0, 180.0, true));
    return n;
  });
}

void lightKeys(const JsonField& list, Animation& a) {
  const bool spot = a.light.type == LightType::Spot;
  const Names own = spot ? Names{"eye", "target", "fov"} : Names{"direction", "target", "extent"};
  const Names other = spot ? Names{"direction", "extent"} : Names{"eye", "fov"};
  keyList(list, a.frames, [&](const JsonField& k, int frame) {
    for (const auto& name : other)
      if (k.has(name))
        k.failAt(name, std::string("a ") + (spot ? "spot" : "directional") + " light has no " + name +
                           " (its keys may give " + joinNames(own) + ")");
    Names allowed = own;
    allowed.push_back("frame");
    allowKeys(k, allowed);
    int n = 0;
    if (const auto v = k.find("eye")) n += addKey(a.lightEye, frame, vec3(*v));
    if (const auto v = k.find("target")) n += addKey(a.lightTarget, frame, vec3(*v));
    if (const auto v = k.find("fov")) n += addKey(a.lightFov, frame, bounded(*v, 0.0, 180.0, true));
    if (const auto v = k.find("extent")) n += addKey(a.lightExtent, frame, positive(*v));
    if (const auto v = k.find("direction")) {
      const glm::vec3 unit = direction(*v);
      // Opposite directions have no one great circle between them.
      if (!a.lightDirection.empty() && glm::dot(a.lightDirection.keys.back().second, unit) < -0.9999f)
        v->fail("is opposite to the previous key's: the great circle between them is undefined");
      n += addKey(a.lightDirection, frame, unit);
    }
    return n;
  });
}

void objectTracks(const JsonField& list, Animation& a, std::size_t objectCount) {
  const std::size_t count = nonEmptyArray(list, "a non-empty array of {\"object\": index, \"keys\": [...]}");
  for (std::size_t i = 0; i < count; ++i) {
    const JsonField entry = list[i].object();
    allowKeys(entry, {"object", "keys"});
    ObjectAnimation track;
    const int last = int(objectCount) - 1;
    const JsonField object = entry["object"];
    track.object = std::size_t(object.integer(0, last));
    for (const auto& other : a.objects)
      if (other.object == track.object)
        object.fail("objects[" + std::to_string(track.object) + "] is animated twice");
    keyList(entry["keys"], a.frames, [&](const JsonField& o, int frame) {
      allowKeys(o, {"frame", "scale", "rotate", "translate"});
      int n = 0;
      if (const auto v = o.find("scale")) n += addKey(track.scale, frame, scaleValue(*v));
      if (const auto v = o.find("rotate")) n += addKey(track.rotate, frame, vec3(*v));
      if (const auto v = o.find("translate")) n += addKey(track.translate, frame, vec3(*v));
      return n;
    });
    a.objects.push_back(std::move(track));
  }
}

// Every frame's camera and light must pass the checks a still scene's do.
void checkFrames(const Animation& a, const JsonField& block) {
  static const nlohmann::json kNothingWritten = nlohmann::json::object();
  const bool camera = !a.cameraEye.empty() || !a.cameraTarget.empty() || !a.cameraFovY.empty();
  const bool light = !a.lightEye.empty() || !a.lightTarget.empty() || !a.lightDirection.empty() ||
                     !a.lightFov.empty() || !a.lightExtent.empty();
  const JsonField cameraAt(kNothingWritten, block.file(), keyPath(block.path(), "camera"));
  const JsonField lightAt(kNothingWritten, block.file(), keyPath(block.path(), "light"));
  for (int frame = 0; frame < a.frames && (camera || light); ++frame) {
    try {
      if (camera) checkCamera(testbed::cameraAt(a, frame), cameraAt);
      if (light) {
        const LightDesc l = testbed::lightAt(a, frame);
        if (l.type == LightType::Spot && l.eye == l.target) lightAt.fail("eye and target meet");
        checkLightTransforms(l, lightAt);
      }
    } catch (const InputError& e) {
      throw InputError(std::string(e.what()) + " (at frame " + std::to_string(frame) + ")");
    }
  }
}

}  // namespace

Animation readAnimation(const JsonField& block, const CameraDesc& camera, const LightDesc& light,
                        std::size_t objectCount) {
  allowKeys(block, {"frames", "fps", "camera", "light", "objects"});
  Animation a;
  a.camera = camera;
  a.light = light;
  a.frames = block["frames"].integer(1, kMaxAnimationFrames);
  a.fps = optionalInteger(block, "fps", 30, 1, 240);
  if (const auto keys = block.find("camera")) cameraKeys(*keys, a);
  if (const auto keys = block.find("light")) lightKeys(*keys, a);
  if (const auto objects = block.find("objects")) objectTracks(*objects, a, objectCount);
  checkFrames(a, block);
  return a;
}

// Every frame's placement must be finite, not only the keys': a rotation between two keys
// turns the mesh, so a coordinate can be largest at no key (a long box swung through
// 90°). One bound covers every frame: |R·S·q + t| ≤ max|S|·|q| + |t| for each fitted
// vertex q, where scale and translate, interpolated linearly, never exceed their largest
// key (or the scene's value where a track has no key). The bound is taken on |fit|·|p|
// term by term and with room to spare, since the float matrix products add terms of that
// size before they cancel.
void checkAnimatedObjects(Animation& a, const std::vector<SceneObject>& objects, const JsonField& block) {
  constexpr double kMaxPlacedCoordinate = std::numeric_limits<float>::max() / 64.0;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    ObjectAnimation& track = a.objects[i];
    const SceneObject& object = objects[track.object];
    track.base = object.pose;
    double scale = 0, translate = 0;
    auto largest = [](double& out, const Track<glm::vec3>& t, glm::vec3 fallback) {
      auto grow = [&out](glm::vec3 v) {
        for (int c = 0; c < 3; ++c) out = std::max(out, std::abs(double(v[c])));
      };
      if (t.empty()) grow(fallback);
      for (const auto& [frame, value] : t.keys) grow(value);
    };
    largest(scale, track.scale, track.base.scale);
    largest(translate, track.translate, track.base.translate);
    double reach = 0;  // largest coordinate of |fit|·(|p|, 1) over the mesh
    for (const auto v : object.local->vertices()) {
      const auto& p = object.local->point(v);
      for (int r = 0; r < 3; ++r) {
        double sum = std::abs(double(object.fit[3][r]));
        for (int c = 0; c < 3; ++c) sum += std::abs(double(object.fit[c][r])) * std::abs(double(p[c]));
        reach = std::max(reach, sum);
      }
    }
    if (!(3 * scale * reach + translate <= kMaxPlacedCoordinate))
      block["objects"][i].fail("transformed coordinates could be not finite between keys (beyond " +
                               showNumber(kMaxPlacedCoordinate) + "; scale or translate too large?)");
  }
}

}  // namespace testbed::scene_file
