#include "testbed/scene/animation.h"

#include <algorithm>
#include <cmath>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtx/rotate_vector.hpp>

#include "testbed/core/error.h"

namespace testbed {
namespace {

// The keys around `frame` and the weight of the later one; `before` == `after` when held.
template <class T>
struct Bracket {
  const T* before;
  const T* after;
  float t;
};

template <class T>
Bracket<T> bracket(const Track<T>& track, int frame) {
  const auto& keys = track.keys;
  if (frame <= keys.front().first) return {&keys.front().second, &keys.front().second, 0.0f};
  if (frame >= keys.back().first) return {&keys.back().second, &keys.back().second, 0.0f};
  const auto after = std::upper_bound(keys.begin(), keys.end(), frame,
                                      [](int f, const auto& key) { return f < key.first; });
  const auto before = after - 1;
  const float t = float(frame - before->first) / float(after->first - before->first);
  return {&before->second, &after->second, t};
}

}  // namespace

glm::mat4 ObjectPose::matrix() const {
  const glm::vec3 radians = glm::radians(rotateDegrees);
  const glm::mat4 rotation = glm::rotate(glm::mat4(1.0f), radians.z, {0, 0, 1}) *
                             glm::rotate(glm::mat4(1.0f), radians.y, {0, 1, 0}) *
                             glm::rotate(glm::mat4(1.0f), radians.x, {1, 0, 0});
  return glm::translate(glm::mat4(1.0f), translate) * rotation * glm::scale(glm::mat4(1.0f), scale);
}

glm::vec3 valueAt(const Track<glm::vec3>& track, int frame, glm::vec3 fallback) {
  if (track.empty()) return fallback;
  const auto b = bracket(track, frame);
  return b.t == 0.0f ? *b.before : glm::mix(*b.before, *b.after, b.t);
}

float valueAt(const Track<float>& track, int frame, float fallback) {
  if (track.empty()) return fallback;
  const auto b = bracket(track, frame);
  return b.t == 0.0f ? *b.before : *b.before + (*b.after - *b.before) * b.t;
}

glm::vec3 directionAt(const Track<glm::vec3>& track, int frame, glm::vec3 fallback) {
  if (track.empty()) return fallback;
  const auto b = bracket(track, frame);
  if (b.t == 0.0f) return *b.before;
  const glm::vec3 from = glm::normalize(*b.before), to = glm::normalize(*b.after);
  // slerp divides by the sine of the angle between the keys, 0 for equal keys. Below
  // 0.01 rad the chord's normalized point is the arc's to within 3·10⁻⁸ rad, under float's
  // resolution of a unit vector.
  if (glm::dot(from, to) > 0.99995f) return glm::normalize(glm::mix(from, to, b.t));
  return glm::normalize(glm::slerp(from, to, b.t));
}

std::optional<glm::vec3> unitDirection(glm::vec3 v) {
  const float largest = glm::max(glm::abs(v.x), glm::max(glm::abs(v.y), glm::abs(v.z)));
  if (!(largest > 0.0f) || !std::isfinite(largest)) return std::nullopt;
  const glm::vec3 unit = glm::normalize(v / largest);
  if (!std::isfinite(unit.x) || !std::isfinite(unit.y) || !std::isfinite(unit.z)) return std::nullopt;
  return unit;
}

CameraDesc cameraAt(const Animation& a, int frame) {
  CameraDesc camera = a.camera;
  camera.eye = valueAt(a.cameraEye, frame, camera.eye);
  camera.target = valueAt(a.cameraTarget, frame, camera.target);
  camera.fovYDegrees = valueAt(a.cameraFovY, frame, camera.fovYDegrees);
  return camera;
}

LightDesc lightAt(const Animation& a, int frame) {
  LightDesc light = a.light;
  light.eye = valueAt(a.lightEye, frame, light.eye);
  light.target = valueAt(a.lightTarget, frame, light.target);
  light.direction = directionAt(a.lightDirection, frame, light.direction);
  light.fovDegrees = valueAt(a.lightFov, frame, light.fovDegrees);
  light.extent = valueAt(a.lightExtent, frame, light.extent);
  return light;
}

ObjectPose poseAt(const ObjectAnimation& a, int frame) {
  return {valueAt(a.scale, frame, a.base.scale), valueAt(a.rotate, frame, a.base.rotateDegrees),
          valueAt(a.translate, frame, a.base.translate)};
}

bool placeMesh(const TriMesh& local, const glm::mat4& model, TriMesh& out) {
  TriMesh placed = local;
  for (const auto v : placed.vertices()) {
    const auto& p = placed.point(v);
    const glm::vec4 q = model * glm::vec4(p[0], p[1], p[2], 1.0f);
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) return false;
    placed.set_point(v, {q.x, q.y, q.z});
  }
  // Recomputing from the moved points handles non-uniform scale without an inverse transpose.
  placed.update_normals();
  out = std::move(placed);
  return true;
}

FrameChange applyFrame(Scene& scene, int frame) {
  FrameChange change;
  if (!scene.animation) {
    if (frame != 0) throw InputError(scene.file.string() + ": has no animation, so only frame 0");
    return change;
  }
  const Animation& a = *scene.animation;
  if (frame < 0 || frame >= a.frames)
    throw InputError(scene.file.string() + ": frame " + std::to_string(frame) + " is outside [0, " +
                     std::to_string(a.frames - 1) + "]");
  const CameraDesc camera = cameraAt(a, frame);
  const LightDesc light = lightAt(a, frame);
  change.camera = !(camera == scene.camera);
  change.light = !(light == scene.light);
  scene.camera = camera;
  scene.light = light;
  for (const auto& track : a.objects) {
    SceneObject& object = scene.objects[track.object];
    const ObjectPose pose = poseAt(track, frame);
    if (pose == object.pose) continue;
    // The parser bounded the placement over every frame (animation_reader.cpp, checkAnimatedObjects).
    if (!placeMesh(*object.local, pose.matrix() * object.fit, object.mesh))
      throw InputError(scene.file.string() + ": " + object.label + ": transformed coordinates at frame " +
                       std::to_string(frame) + " are not finite");
    object.pose = pose;
    change.objects.push_back(track.object);
  }
  if (!change.objects.empty()) ++scene.geometryRevision;
  return change;
}

}  // namespace testbed
