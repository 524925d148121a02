// Reading a scene file: its document, camera, light and objects (meshes and primitives),
// through the checked JSON reader (io/json_reader.h). Scene files are hand-written, so
// every mistake is reported as one line naming the file and the JSON key path
// ("scenes/x.json: objects[1].scale: must be > 0, got -2"), and no partially valid scene
// is ever returned. The value checks live in scene_values.h, the animation block's
// reading in animation_reader.h.
#include <OpenMesh/Core/IO/MeshIO.hh>  // must precede the mesh type header
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/io/json_reader.h"
#include "testbed/scene/animation.h"
#include "testbed/scene/animation_reader.h"
#include "testbed/scene/camera_check.h"
#include "testbed/scene/primitives.h"
#include "testbed/scene/scene.h"
#include "testbed/scene/scene_values.h"
#include "testbed_build_paths.h"

namespace testbed {
namespace scene_file {
namespace {

namespace fs = std::filesystem;

// Guards against absurd subdivide/segments values before any memory is spent on them.
constexpr std::uint64_t kMaxSceneTriangles = 20'000'000;

CameraDesc readCamera(const JsonField& value) {
  allowKeys(value, {"eye", "target", "up", "fov_y", "near", "far"});
  CameraDesc camera;
  camera.eye = vec3(value["eye"]);
  camera.target = vec3(value["target"]);
  if (const auto up = value.find("up")) camera.up = vec3(*up);
  camera.fovYDegrees = optionalBounded(value, "fov_y", 45.0, 0.0, 180.0);
  nearFar(value, camera.nearPlane, camera.farPlane);
  checkCamera(camera, value);
  return camera;
}

void readSpotLight(const JsonField& value, LightDesc& light) {
  allowKeys(value, {"type", "eye", "target", "fov", "near", "far", "radius", "fit"});
  light.type = LightType::Spot;
  light.eye = vec3(value["eye"]);
  light.target = vec3(value["target"]);
  if (light.eye == light.target) value.failAt("target", "must differ from light.eye");
  light.fovDegrees = optionalBounded(value, "fov", 45.0, 0.0, 180.0);
  nearFar(value, light.nearPlane, light.farPlane);
}

void readDirectionalLight(const JsonField& value, LightDesc& light) {
  allowKeys(value, {"type", "direction", "target", "extent", "radius", "fit"});
  light.type = LightType::Directional;
  light.direction = direction(value["direction"]);
  light.target = glm::vec3(0.0f);
  if (const auto target = value.find("target")) light.target = vec3(*target);
  // Without an extent the square is fitted to the scene, which needs fitting on.
  light.extent = 0.0f;
  if (const auto extent = value.find("extent")) light.extent = positive(*extent);
  else if (!light.fit) value.failAt("extent", "missing required key (needed when light.fit is false)");
}

LightDesc readLight(const JsonField& value) {
  value.object();
  LightDesc light;
  const JsonField type = value["type"];
  if (const auto fit = value.find("fit")) light.fit = fit->boolean();
  if (type.word({"spot", "directional"}) == 0) readSpotLight(value, light);
  else readDirectionalLight(value, light);
  light.radius = optionalBounded(value, "radius", 0.0, 0.0, kUnbounded, false);
  checkLightTransforms(light, value);
  return light;
}

// A mesh name ("bunny": an asset) or a file path, relative to the scene file's folder.
fs::path resolveMesh(const JsonField& source) {
  const std::string name = source.text();
  if (name.empty()) source.fail("expected a mesh name or file path, got \"\"");
  const fs::path asPath(name);
  std::string assetLooked;
  std::error_code ec;
  if (name.find('/') == std::string::npos && !asPath.has_extension()) {
    const fs::path base = assetDirectory() / name;
    for (const char* ext : {".off", ".obj", ".ply", ".stl"}) {
      fs::path candidate = base;
      candidate += ext;
      if (fs::is_regular_file(candidate, ec)) return candidate;
    }
    assetLooked = base.string() + ".{off,obj,ply,stl} and ";
  }
  const fs::path local = asPath.is_absolute() ? asPath : fs::path(source.file()).parent_path() / asPath;
  if (fs::exists(local, ec)) return local;
  source.fail("mesh \"" + name + "\" not found (looked for " + assetLooked + local.string() + ")");
}

void addTriangles(std::uint64_t& triangles, std::uint64_t count, int subdivide, const JsonField& object) {
  triangles += count << (2 * subdivide);  // each Loop level quadruples the triangles
  if (triangles > kMaxSceneTriangles)
    object.fail("the scene would have " + std::to_string(triangles) + " triangles, more than the limit of " +
                std::to_string(kMaxSceneTriangles) + " (lower subdivide or segments)");
}

// A fixed-length list of positive sizes, e.g. a plane's [x, z].
std::vector<float> sizes(const JsonField& value, std::size_t n, const char* form) {
  value.arrayOf(n, form);
  std::vector<float> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(positive(value[i]));
  return out;
}

TriMesh readPrimitive(const JsonField& value, const std::string& kind, int subdivide, std::uint64_t& triangles) {
  Names keys = {"primitive", "scale", "rotate", "translate", "subdivide"};
  auto own = [&](const Names& extra) {
    keys.insert(keys.end(), extra.begin(), extra.end());
    allowKeys(value, keys);
  };
  auto budget = [&](std::uint64_t count) { addTriangles(triangles, count, subdivide, value); };
  auto req = [&](const char* name) { return positive(value[name]); };
  auto segments = [&](const char* name, int fallback, int lo) { return optionalInteger(value, name, fallback, lo, 1024); };
  if (kind == "plane") {
    own({"size", "segments"});
    const auto size = sizes(value["size"], 2, "[x, z]");
    const int n = segments("segments", 1, 1);
    budget(2ull * n * n);
    return makePlane(size[0], size[1], n);
  }
  if (kind == "box") {
    own({"size"});
    const auto size = sizes(value["size"], 3, "[x, y, z]");
    budget(12);
    return makeBox(size[0], size[1], size[2]);
  }
  if (kind == "sphere") {
    own({"radius", "segments", "rings"});
    const float radius = req("radius");
    const int n = segments("segments", 32, 3), rings = segments("rings", 16, 2);
    budget(2ull * n * (rings - 1));
    return makeSphere(radius, n, rings);
  }
  if (kind == "cylinder") {
    own({"radius", "height", "segments"});
    const float radius = req("radius"), height = req("height");
    const int n = segments("segments", 32, 3);
    budget(4ull * n);
    return makeCylinder(radius, height, n);
  }
  if (kind == "torus") {
    own({"major", "minor", "segments", "tube_segments"});
    const float major = req("major"), minor = req("minor");
    if (!(minor < major))
      value.failAt("minor", "must be smaller than major (" + showNumber(major) + "), got " + showNumber(minor));
    const int n = segments("segments", 48, 3), tube = segments("tube_segments", 16, 3);
    budget(2ull * n * tube);
    return makeTorus(major, minor, n, tube);
  }
  if (kind == "fence") {
    own({"width", "height", "bars", "bar_width", "bar_depth", "rails"});
    const float width = req("width"), height = req("height");
    const int bars = value["bars"].integer(1, 1024);
    const float barWidth = req("bar_width"), barDepth = req("bar_depth");
    const int rails = optionalInteger(value, "rails", 2, 0, 64);
    budget(12ull * (bars + rails));
    return makeFence(width, height, bars, barWidth, barDepth, rails);
  }
  value.failAt("primitive", "unknown primitive " + briefJson(nlohmann::json(kind)) +
                                " (expected plane, box, sphere, cylinder, torus or fence)");
}

// fit, then scale, rotate (X, then Y, then Z) and translate.
void placeObject(const JsonField& value, SceneObject& object) {
  TriMesh& mesh = object.mesh;
  glm::mat4 model(1.0f);
  if (const auto fit = value.find("fit")) {
    const float target = positive(*fit);
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const auto v : mesh.vertices()) {
      const auto& p = mesh.point(v);
      lo = glm::min(lo, glm::vec3(p[0], p[1], p[2]));
      hi = glm::max(hi, glm::vec3(p[0], p[1], p[2]));
    }
    const glm::vec3 extent = hi - lo;
    const float largest = std::max({extent.x, extent.y, extent.z});
    if (!(largest > 0)) fit->fail("the mesh has zero size");
    model = glm::scale(glm::mat4(1.0f), glm::vec3(target / largest)) * glm::translate(glm::mat4(1.0f), -(lo + hi) * 0.5f);
  }
  ObjectPose& pose = object.pose;
  if (const auto s = value.find("scale")) pose.scale = scaleValue(*s);
  if (const auto r = value.find("rotate")) pose.rotateDegrees = vec3(*r);
  if (const auto t = value.find("translate")) pose.translate = vec3(*t);
  object.fit = model;
  if (!placeMesh(mesh, pose.matrix() * model, mesh))
    value.fail("transformed coordinates are not finite (scale or translate too large?)");
}

SceneObject readObject(const JsonField& value, std::uint64_t& triangles, bool animated) {
  value.object();
  const bool isMesh = value.has("mesh");
  if (isMesh && value.has("primitive")) value.fail("has both \"mesh\" and \"primitive\"; give exactly one");
  if (!isMesh && !value.has("primitive")) value.fail("needs either \"mesh\" or \"primitive\"");
  const JsonField source = value[isMesh ? "mesh" : "primitive"];
  const std::string name = source.text();
  // Validate the keys first so that a typo is reported before a slow mesh load.
  if (isMesh) allowKeys(value, {"mesh", "fit", "scale", "rotate", "translate", "subdivide"});
  const int subdivide = optionalInteger(value, "subdivide", 0, 0, 4);

  SceneObject object;
  object.label = value.path() + (isMesh ? " (mesh " : " (primitive ") + name + ")";
  if (isMesh) {
    const fs::path path = resolveMesh(source);
    try {
      object.mesh = readMeshFile(path);
    } catch (const InputError& e) {
      source.fail(e.what());
    }
    addTriangles(triangles, object.mesh.n_faces(), subdivide, value);
  } else {
    object.mesh = readPrimitive(value, name, subdivide, triangles);
  }
  if (subdivide > 0) {
    OpenMesh::Subdivider::Uniform::LoopT<TriMesh> loop;
    loop.attach(object.mesh);
    loop(static_cast<std::size_t>(subdivide));
    loop.detach();
  }
  if (animated) object.local = std::make_shared<const TriMesh>(object.mesh);
  placeObject(value, object);
  return object;
}

Scene readScene(const JsonField& top) {
  if (!top.json().is_object()) top.fail("expected a JSON object at the top level, got " + top.brief());
  allowKeys(top, {"name", "camera", "light", "objects", "animation"});
  Scene scene;
  scene.file = top.file();
  scene.name = scene.file.stem().string();
  if (const auto name = top.find("name")) {
    if (!name->json().is_string() || name->json().get_ref<const std::string&>().empty())
      name->fail("expected a non-empty string, got " + name->brief());
    scene.name = name->text();
  }
  scene.camera = readCamera(top["camera"].object());
  scene.light = readLight(top["light"]);
  const JsonField objects = top["objects"];
  const std::size_t count = nonEmptyArray(objects, "a non-empty array of objects");
  std::shared_ptr<Animation> animation;
  std::vector<bool> animated(count, false);
  const auto block = top.find("animation");
  if (block) {
    animation = std::make_shared<Animation>(readAnimation(*block, scene.camera, scene.light, count));
    for (const auto& track : animation->objects) animated[track.object] = true;
  }
  std::uint64_t triangles = 0;
  for (std::size_t i = 0; i < count; ++i) scene.objects.push_back(readObject(objects[i], triangles, animated[i]));
  if (animation) {
    checkAnimatedObjects(*animation, scene.objects, *block);
    scene.animation = animation;
    applyFrame(scene, 0);  // a loaded animated scene is its first frame
  }
  return scene;
}

}  // namespace
}  // namespace scene_file

namespace fs = std::filesystem;

fs::path assetDirectory() {
  if (const char* dir = std::getenv("TESTBED_ASSET_DIR"); dir && *dir) return dir;
  return TESTBED_DEFAULT_ASSET_DIR;
}

Scene parseScene(const nlohmann::json& document, const fs::path& file) {
  return scene_file::readScene(JsonField(document, file.string()));
}

void checkCamera(const CameraDesc& camera, const fs::path& where) {
  static const nlohmann::json kNothingWritten = nlohmann::json::object();
  scene_file::checkCamera(camera, JsonField(kNothingWritten, where.string(), "camera"));
}

Scene loadScene(const fs::path& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw InputError(file.string() + ": is a folder, not a scene file");
  return parseScene(readJsonInput(file), file);
}

}  // namespace testbed
