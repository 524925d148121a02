#pragma once
// An animated scene's `animation` block (docs/motion.md "Animation block"): key frames for
// the camera, the light and object transforms, evaluated at any frame. Each field has its
// own track, made of the keys that give it: between two of them it is interpolated
// linearly (a directional light's direction along the great circle), before the first and
// after the last it holds, and without any key it keeps the scene's static value.
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/scene/scene.h"

namespace testbed {

template <class T>
struct Track {
  std::vector<std::pair<int, T>> keys;  // (frame, value), frames strictly increasing
  bool empty() const { return keys.empty(); }
};

struct ObjectAnimation {
  std::size_t object = 0;  // index in Scene::objects
  ObjectPose base;         // the scene file's placement, which the tracks replace
  Track<glm::vec3> scale, rotate, translate;
};

struct Animation {
  int frames = 1;
  int fps = 30;
  CameraDesc camera;  // the static values the tracks replace (the scene file's)
  LightDesc light;
  Track<glm::vec3> cameraEye, cameraTarget;
  Track<float> cameraFovY;
  Track<glm::vec3> lightEye, lightTarget, lightDirection;  // direction: unit vectors
  Track<float> lightFov, lightExtent;
  std::vector<ObjectAnimation> objects;
};

// A track's value at `frame`: `fallback` without keys, held outside the keys, linear
// between them.
glm::vec3 valueAt(const Track<glm::vec3>& track, int frame, glm::vec3 fallback);
float valueAt(const Track<float>& track, int frame, float fallback);
// Unit directions interpolated along the great circle; two keys of the same direction
// (or closer than float resolves an angle) hold it.
glm::vec3 directionAt(const Track<glm::vec3>& track, int frame, glm::vec3 fallback);
// v / |v|, computed without overflow or underflow in |v| (v is first divided by its largest
// component, so [1e38, -1e38, 0] is (1, -1, 0)/√2); empty for a zero or non-finite v.
std::optional<glm::vec3> unitDirection(glm::vec3 v);

CameraDesc cameraAt(const Animation& animation, int frame);
LightDesc lightAt(const Animation& animation, int frame);
ObjectPose poseAt(const ObjectAnimation& animation, int frame);

// `model` (ObjectPose::matrix() · SceneObject::fit) applied to `local`, normals recomputed.
// False, and `out` untouched, when a transformed coordinate is not finite.
bool placeMesh(const TriMesh& local, const glm::mat4& model, TriMesh& out);

// What applyFrame changed, so that only that is redone.
struct FrameChange {
  bool camera = false, light = false;
  std::vector<std::size_t> objects;  // indices of the objects that moved
  bool any() const { return camera || light || !objects.empty(); }
};

// Sets the scene's camera, light and animated objects to their values at `frame` (in
// [0, frames − 1]; a scene without animation has only frame 0) and says what changed.
// Moving an object rebuilds its world-space mesh and bumps Scene::geometryRevision.
FrameChange applyFrame(Scene& scene, int frame);

}  // namespace testbed
