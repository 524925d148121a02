#pragma once
// Scene description as read from a JSON scene file (format: docs/scenes.md "Scenes").
// Everything here is CPU-side and validated; GPU upload lives in render/gpu_scene.h.
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>

#include "testbed/scene/mesh.h"

namespace testbed {

struct CameraDesc {
  glm::vec3 eye{0, 0, 5};
  glm::vec3 target{0, 0, 0};
  glm::vec3 up{0, 1, 0};
  float fovYDegrees = 45.0f;
  float nearPlane = 1.0f;
  float farPlane = 1000.0f;
  bool operator==(const CameraDesc&) const = default;
};

enum class LightType { Spot, Directional };

struct LightDesc {
  LightType type = LightType::Spot;
  // Spot: perspective shadow map from `eye` towards `target` with a square `fovDegrees`.
  glm::vec3 eye{0, 10, 0};
  glm::vec3 target{0, 0, 0};
  float fovDegrees = 45.0f;
  float nearPlane = 1.0f;  // with `fit`: limits of the fitted range
  float farPlane = 1000.0f;
  // Directional: orthographic shadow map along `direction` (light travel direction),
  // covering the square of half size `extent` centred on `target` (0: fitted to the scene).
  glm::vec3 direction{0, -1, 0};
  float extent = 10.0f;
  // Fit the depth range (spot: within [nearPlane, farPlane]; directional: all geometry in
  // the footprint, and the extent when it is 0) to the scene's geometry (light_fit.h).
  bool fit = true;
  // Only the area-light reference uses the radius (disk around the light position).
  float radius = 0.0f;
  bool operator==(const LightDesc&) const = default;
};

// An object's placement as the scene file gives it: scale, then rotate (degrees about X,
// then Y, then Z), then translate.
struct ObjectPose {
  glm::vec3 scale{1.0f}, rotateDegrees{0.0f}, translate{0.0f};
  glm::mat4 matrix() const;
  bool operator==(const ObjectPose&) const = default;
};

struct SceneObject {
  std::string label;  // for messages: "objects[1] (mesh bunny)"
  TriMesh mesh;       // world space, triangulated, face and vertex normals filled in
  ObjectPose pose;    // the placement `mesh` has now
  glm::mat4 fit{1.0f};  // the object's "fit" (scale to size, centred), applied before `pose`
  // Animated objects only: the mesh before `fit` and `pose`, to place it again per frame.
  std::shared_ptr<const TriMesh> local;
};

struct Animation;  // scene/animation.h

struct Scene {
  std::string name;
  std::filesystem::path file;  // the scene file it came from (empty if built in code)
  CameraDesc camera;
  LightDesc light;
  std::vector<SceneObject> objects;
  std::shared_ptr<const Animation> animation;  // null: a still scene
  // Bumped whenever an object's mesh changes (scene/animation.h applyFrame), so that what
  // is derived from the meshes knows when to derive it again.
  std::uint64_t geometryRevision = 0;
};

// Folder of the asset meshes that scenes name ("mesh": "bunny" → <dir>/bunny.off).
// $TESTBED_ASSET_DIR overrides the folder configured at build time.
std::filesystem::path assetDirectory();

// Reads and validates a scene file. Throws InputError("<file>: <key path>: <problem>")
// for a missing file, bad JSON, an unknown key, a wrong type, NaN/Inf, a non-positive
// size, a missing/empty/broken mesh, and so on. Never returns a half-valid scene.
Scene loadScene(const std::filesystem::path& file);

// The same from an already parsed document; `file` is used for messages and to resolve
// relative mesh paths (relative to the file's folder).
Scene parseScene(const nlohmann::json& document, const std::filesystem::path& file);

// Reads one mesh (OFF/OBJ/PLY/STL) with OpenMesh. Throws InputError naming `file` when it
// is missing, unreadable, has no triangles, or has non-finite coordinates.
TriMesh readMeshFile(const std::filesystem::path& file);

}  // namespace testbed
