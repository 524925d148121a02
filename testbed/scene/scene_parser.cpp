// Scene files are hand-written, so every mistake is reported as one line naming the file
// and the JSON key path ("scenes/x.json: objects[1].scale: must be > 0, got -2"), and no
// partially valid scene is ever returned.
#include <OpenMesh/Core/IO/MeshIO.hh>  // must precede the mesh type header
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"
#include "testbed/scene/animation.h"
#include "testbed/scene/camera_check.h"
#include "testbed/scene/primitives.h"
#include "testbed/scene/scene.h"
#include "testbed/scene/view.h"
#include "testbed_build_paths.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using Names = std::vector<std::string>;

// Guards against absurd subdivide/segments values before any memory is spent on them.
constexpr std::uint64_t kMaxSceneTriangles = 20'000'000;
constexpr double kUnbounded = std::numeric_limits<double>::infinity();
// An animation's frames are rendered one by one; this bounds a typo, not a real sequence.
constexpr int kMaxFrames = 100'000;

// A value for "got ...": one short line whatever the input holds.
std::string show(const json& value) { return briefJson(value); }

std::string show(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string join(const Names& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

// The JSON key path of a value: "objects[2].mesh", "camera.eye[1]".
struct Key {
  std::string path;
  Key operator/(const std::string& name) const { return {keyPath(path, name)}; }
  Key operator[](std::size_t index) const { return {indexPath(path, index)}; }
};

class Parser {
 public:
  explicit Parser(const fs::path& file) : file_(file) {}

  Scene scene(const json& document) const {
    const Key top;
    if (!document.is_object())
      fail(top, "expected a JSON object at the top level, got " + show(document));
    checkKeys(document, top, {"name", "camera", "light", "objects", "animation"});
    Scene scene;
    scene.file = file_;
    scene.name = file_.stem().string();
    if (const json* name = find(document, "name")) {
      if (!name->is_string() || name->get<std::string>().empty()) {
        fail(top / "name", "expected a non-empty string, got " + show(*name));
      }
      scene.name = name->get<std::string>();
    }
    scene.camera = camera(require(document, top, "camera"), top / "camera");
    scene.light = light(require(document, top, "light"), top / "light");
    const json& objects = require(document, top, "objects");
    if (!objects.is_array() || objects.empty()) {
      fail(top / "objects", "expected a non-empty array of objects, got " + show(objects));
    }
    std::shared_ptr<Animation> animation;
    std::vector<bool> animated(objects.size(), false);
    if (const json* block = find(document, "animation")) {
      animation = std::make_shared<Animation>(
          this->animation(*block, top / "animation", scene.camera, scene.light, objects.size()));
      for (const auto& track : animation->objects) animated[track.object] = true;
    }
    std::uint64_t triangles = 0;
    for (std::size_t i = 0; i < objects.size(); ++i) {
      scene.objects.push_back(sceneObject(objects[i], (top / "objects")[i], triangles, animated[i]));
    }
    if (animation) {
      checkAnimatedObjects(*animation, scene.objects, top / "animation" / "objects");
      scene.animation = animation;
      applyFrame(scene, 0);  // a loaded animated scene is its first frame
    }
    return scene;
  }

  [[noreturn]] void fail(const Key& key, const std::string& problem) const {
    throw InputError(file_.string() + ": " + (key.path.empty() ? "" : key.path + ": ") + problem);
  }

 private:
  // Unknown keys are errors, never warnings: a typo must not silently fall back to a default.
  void checkKeys(const json& object, const Key& key, Names allowed) const {
    allowed.push_back("comment");
    for (const auto& [name, value] : object.items()) {
      if (std::find(allowed.begin(), allowed.end(), name) == allowed.end()) {
        fail(key / name, "unknown key (allowed here: " + join(allowed) + ")");
      }
      if (name == "comment" && !value.is_string()) {
        fail(key / name, "expected a string, got " + show(value));
      }
    }
  }

  void requireObject(const json& value, const Key& key) const {
    if (!value.is_object()) fail(key, "expected a JSON object {...}, got " + show(value));
  }

  static const json* find(const json& object, const char* name) {
    const auto it = object.find(name);
    return it == object.end() ? nullptr : &*it;
  }

  const json& require(const json& object, const Key& key, const char* name) const {
    const json* value = find(object, name);
    if (!value) fail(key / name, "missing required key");
    return *value;
  }

  double number(const json& value, const Key& key) const {
    if (!value.is_number()) fail(key, "expected a number, got " + show(value));
    const double x = value.get<double>();
    if (!std::isfinite(x)) fail(key, "not a finite number");
    // Everything ends up in floats; 1e300 would silently become infinity there.
    if (std::abs(x) > std::numeric_limits<float>::max()) fail(key, "too large, got " + show(value));
    return x;
  }

  // Range checks run on the float that is kept, so that 1e-50 cannot pass as "> 0".
  float positive(const json& value, const Key& key) const {
    const float x = float(number(value, key));
    if (!(x > 0)) fail(key, "must be > 0, got " + show(value));
    return x;
  }

  // Within [lo, hi) (or (lo, hi) when loOpen); hi may be infinite.
  float bounded(const json& value, const Key& key, double lo, double hi, bool loOpen) const {
    const float x = float(number(value, key));
    if ((loOpen ? x <= lo : x < lo) || !(x < hi)) {
      const std::string upper = std::isinf(hi) ? "" : " and < " + show(hi);
      fail(key, "must be " + std::string(loOpen ? "> " : ">= ") + show(lo) + upper + ", got " +
                    show(value));
    }
    return x;
  }

  float optional(const json& object, const Key& key, const char* name, double fallback, double lo,
                 double hi, bool loOpen = true) const {
    const json* value = find(object, name);
    return value ? bounded(*value, key / name, lo, hi, loOpen) : float(fallback);
  }

  int integer(const json& value, const Key& key, int lo, int hi) const {
    const std::string range =
        "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    const double x = number(value, key);
    if (x != std::floor(x)) fail(key, "expected " + range + ", got " + show(value));
    if (x < lo || x > hi) fail(key, "must be " + range + ", got " + show(value));
    return int(x);
  }

  int optionalInteger(const json& object, const Key& key, const char* name, int fallback, int lo,
                      int hi) const {
    const json* value = find(object, name);
    return value ? integer(*value, key / name, lo, hi) : fallback;
  }

  glm::vec3 vec3(const json& value, const Key& key) const {
    if (!value.is_array() || value.size() != 3) fail(key, "expected [x, y, z], got " + show(value));
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = float(number(value[i], key[i]));
    return v;
  }

  // A direction: any non-zero vector of finite floats, made unit.
  glm::vec3 direction(const json& value, const Key& key) const {
    const std::optional<glm::vec3> unit = unitDirection(vec3(value, key));
    if (!unit) fail(key, "must be a non-zero vector, got " + show(value));
    return *unit;
  }

  // A fixed-length list of positive sizes, e.g. a plane's [x, z].
  std::vector<float> sizes(const json& value, const Key& key, std::size_t n,
                           const char* form) const {
    if (!value.is_array() || value.size() != n)
      fail(key, std::string("expected ") + form + ", got " + show(value));
    std::vector<float> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(positive(value[i], key[i]));
    return out;
  }

  void nearFar(const json& object, const Key& key, float& nearPlane, float& farPlane) const {
    nearPlane = optional(object, key, "near", 1.0, 0.0, kUnbounded);
    farPlane = optional(object, key, "far", 1000.0, 0.0, kUnbounded);
    if (!(farPlane > nearPlane)) {
      fail(key / "far",
           "must be greater than near (" + show(nearPlane) + "), got " + show(farPlane));
    }
  }

  CameraDesc camera(const json& value, const Key& key) const {
    requireObject(value, key);
    checkKeys(value, key, {"eye", "target", "up", "fov_y", "near", "far"});
    CameraDesc camera;
    camera.eye = vec3(require(value, key, "eye"), key / "eye");
    camera.target = vec3(require(value, key, "target"), key / "target");
    if (const json* up = find(value, "up")) camera.up = vec3(*up, key / "up");
    camera.fovYDegrees = optional(value, key, "fov_y", 45.0, 0.0, 180.0);
    nearFar(value, key, camera.nearPlane, camera.farPlane);
    checkCamera(camera, value, key);
    return camera;
  }

 public:
  // Public for the free checkCamera(): the viewer checks its scripted moves with it.
  void checkCamera(const CameraDesc& camera, const json& given, const Key& key) const {
    const glm::vec3 view = camera.target - camera.eye;
    if (camera.eye == camera.target) fail(key / "target", "must differ from camera.eye");
    checkCameraPrecision(camera, given, key);
    const float upLength = glm::length(camera.up);
    if (upLength == 0.0f ||
        glm::length(glm::cross(camera.up / upLength, glm::normalize(view))) < 1e-4f) {
      fail(key / "up", "must be non-zero and not parallel to the view direction");
    }
  }

 private:
  // Values that pass as numbers but whose derived quantities degenerate in the renderer's
  // float arithmetic, giving an all-background image or a late failure instead of an error.
  void checkCameraPrecision(const CameraDesc& camera, const json& given, const Key& key) const {
    // As written in the file: the float kept may print rounded (179.9999 as 180).
    auto written = [&](const char* name, float kept) { return find(given, name) ? show(*find(given, name)) : show(kept); };
    constexpr float kMinFov = 0.1f, kMaxFov = 179.0f;
    if (camera.fovYDegrees < kMinFov || camera.fovYDegrees > kMaxFov)
      fail(key / "fov_y", "must be in [" + show(kMinFov) + ", " + show(kMaxFov) + "] degrees, got " +
                              written("fov_y", camera.fovYDegrees) +
                              " (beyond, pixels are finer than float precision or the image collapses to a point)");
    const float n = camera.nearPlane, f = camera.farPlane;
    constexpr float kMaxDepthRatio = 1e7f, kMinDepthRange = 1e-3f;
    if (f / n > kMaxDepthRatio)
      fail(key / "far", "far/near is " + show(f / n) + ", more than " + show(kMaxDepthRatio) +
                            " (the depth buffer could not tell surfaces apart)");
    if ((f - n) / f < kMinDepthRange)
      fail(key / "far", "must exceed near (" + show(n) + ") by at least " + show(kMinDepthRange * 100) +
                            "% of far, got " + written("far", f) + " (no depth precision is left between them)");
    // The projection as the renderer builds it, in float: near must map to depth -1 and
    // far to +1 (products such as 2·far·near overflow or underflow for extreme planes).
    const glm::mat4 projection = glm::perspective(glm::radians(camera.fovYDegrees), 1.0f, n, f);
    auto ndcDepth = [&](float distance) {
      const glm::vec4 clip = projection * glm::vec4(0.0f, 0.0f, -distance, 1.0f);
      return clip.z / clip.w;
    };
    if (!(std::abs(ndcDepth(n) + 1.0f) < 1e-3f && std::abs(ndcDepth(f) - 1.0f) < 1e-3f))
      fail(key / "far", "near " + show(n) + " and far " + show(f) +
                            " overflow the float projection matrix (use planes nearer to the scene's scale)");
    // The view transform subtracts the eye from every vertex in float: once float spacing at
    // the eye's coordinates reaches the near distance, nothing in front of the camera keeps
    // its place (an eye at 1e30 renders an empty image).
    const float reach = std::max({std::abs(camera.eye.x), std::abs(camera.eye.y), std::abs(camera.eye.z)});
    const float spacing = std::nextafter(reach, std::numeric_limits<float>::infinity()) - reach;
    if (!(spacing < n))
      fail(key / "eye", "coordinates as large as " + show(reach) + " are " + show(spacing) +
                            " apart in float, not finer than near (" + show(n) +
                            "): nothing in front of the camera keeps its place (bring the scene nearer the origin)");
    // A view direction from two points that differ only in their last bits is noise.
    const glm::vec3 view = camera.target - camera.eye;
    const float scale = std::max(glm::length(camera.eye), glm::length(camera.target));
    if (!(glm::length(view) > 1e-5f * scale) || !std::isnormal(glm::dot(view, view)))
      fail(key / "target", "is only " + show(glm::length(glm::dvec3(camera.target) - glm::dvec3(camera.eye))) +
                               " from camera.eye: too close to give a view direction in float precision");
    // Beyond far, the point the camera is aimed at is clipped away with everything around it.
    if (glm::length(view) > f)
      fail(key / "target", "is " + show(glm::length(view)) + " from camera.eye, beyond far (" + show(f) +
                               "): what the camera is aimed at would be clipped away");
  }

  LightDesc light(const json& value, const Key& key) const {
    requireObject(value, key);
    LightDesc light;
    const json& type = require(value, key, "type");
    if (const json* fit = find(value, "fit")) {
      if (!fit->is_boolean()) fail(key / "fit", "expected true or false, got " + show(*fit));
      light.fit = fit->get<bool>();
    }
    if (type == "spot") {
      checkKeys(value, key, {"type", "eye", "target", "fov", "near", "far", "radius", "fit"});
      light.type = LightType::Spot;
      light.eye = vec3(require(value, key, "eye"), key / "eye");
      light.target = vec3(require(value, key, "target"), key / "target");
      if (light.eye == light.target) fail(key / "target", "must differ from light.eye");
      light.fovDegrees = optional(value, key, "fov", 45.0, 0.0, 180.0);
      nearFar(value, key, light.nearPlane, light.farPlane);
    } else if (type == "directional") {
      checkKeys(value, key, {"type", "direction", "target", "extent", "radius", "fit"});
      light.type = LightType::Directional;
      light.direction = direction(require(value, key, "direction"), key / "direction");
      light.target = glm::vec3(0.0f);
      if (const json* target = find(value, "target")) light.target = vec3(*target, key / "target");
      // Without an extent the square is fitted to the scene, which needs fitting on.
      light.extent = 0.0f;
      if (const json* extent = find(value, "extent"))
        light.extent = positive(*extent, key / "extent");
      else if (!light.fit)
        fail(key / "extent", "missing required key (needed when light.fit is false)");
    } else {
      fail(key / "type", "expected \"spot\" or \"directional\", got " + show(type));
    }
    light.radius = optional(value, key, "radius", 0.0, 0.0, kUnbounded, false);
    checkLightTransforms(light, key);
    return light;
  }

  // The light's values as given must make a usable shadow-map transform in float, the
  // precision the GPU works in: a finite view (eye and target far enough apart for a unit
  // direction) and a finite, invertible projection whose scale factors are normal floats
  // (far 1e38 overflows 2·far·near; fov 1e-38 or extent 1e38 underflow the scale).
  void checkLightTransforms(LightDesc light, const Key& key) const {
    const bool spot = light.type == LightType::Spot;
    if (!spot && light.extent == 0.0f) light.extent = 1.0f;  // fitted later: check the rest
    const LightTransforms t = lightTransforms(light);
    auto finite = [](const glm::mat4& m) {
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          if (!std::isfinite(m[c][r])) return false;
      return true;
    };
    auto normal = [](float x) { return std::isnormal(x); };
    if (spot && (!finite(t.view) || !std::isfinite(glm::length(t.direction))))
      fail(key / "target", "too close to light.eye: the light's view direction is not a finite unit vector");
    const glm::mat4& p = t.projection;
    const bool scales = normal(p[0][0]) && normal(p[1][1]) && normal(p[2][2]);
    const glm::mat4 inverse = glm::inverse(t.viewProjection());
    if (finite(t.view) && finite(p) && scales && finite(inverse)) return;
    if (!spot)
      fail(key / "extent", "too large: the light's orthographic projection is not finite and invertible in float, got " +
                               show(light.extent));
    if (!normal(p[0][0]) || !normal(p[1][1]))
      fail(key / "fov", "too small or too close to 180: the light's projection is not finite, got " +
                            show(light.fovDegrees));
    fail(key / "far", "with near " + show(light.nearPlane) + " the light's projection is not finite and invertible in float, got " +
                          show(light.farPlane));
  }

  fs::path resolveMesh(const std::string& name, const Key& key) const {
    if (name.empty()) fail(key, "expected a mesh name or file path, got \"\"");
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
    const fs::path local = asPath.is_absolute() ? asPath : file_.parent_path() / asPath;
    if (fs::exists(local, ec)) return local;
    fail(key, "mesh \"" + name + "\" not found (looked for " + assetLooked + local.string() + ")");
  }

  TriMesh primitive(const json& value, const Key& key, const std::string& kind, int subdivide,
                    std::uint64_t& triangles) const {
    Names keys = {"primitive", "scale", "rotate", "translate", "subdivide"};
    auto own = [&](const Names& extra) {
      keys.insert(keys.end(), extra.begin(), extra.end());
      checkKeys(value, key, keys);
    };
    auto budget = [&](std::uint64_t count) { addTriangles(triangles, count, subdivide, key); };
    auto req = [&](const char* name) { return positive(require(value, key, name), key / name); };
    auto segments = [&](const char* name, int fallback, int lo) {
      return optionalInteger(value, key, name, fallback, lo, 1024);
    };
    if (kind == "plane") {
      own({"size", "segments"});
      const auto size = sizes(require(value, key, "size"), key / "size", 2, "[x, z]");
      const int n = segments("segments", 1, 1);
      budget(2ull * n * n);
      return makePlane(size[0], size[1], n);
    }
    if (kind == "box") {
      own({"size"});
      const auto size = sizes(require(value, key, "size"), key / "size", 3, "[x, y, z]");
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
        fail(key / "minor", "must be smaller than major (" + show(major) + "), got " + show(minor));
      const int n = segments("segments", 48, 3), tube = segments("tube_segments", 16, 3);
      budget(2ull * n * tube);
      return makeTorus(major, minor, n, tube);
    }
    if (kind == "fence") {
      own({"width", "height", "bars", "bar_width", "bar_depth", "rails"});
      const float width = req("width"), height = req("height");
      const int bars = integer(require(value, key, "bars"), key / "bars", 1, 1024);
      const float barWidth = req("bar_width"), barDepth = req("bar_depth");
      const int rails = optionalInteger(value, key, "rails", 2, 0, 64);
      budget(12ull * (bars + rails));
      return makeFence(width, height, bars, barWidth, barDepth, rails);
    }
    fail(key / "primitive", "unknown primitive " + show(json(kind)) +
                                " (expected plane, box, sphere, cylinder, torus or fence)");
  }

  void addTriangles(std::uint64_t& triangles, std::uint64_t count, int subdivide,
                    const Key& key) const {
    triangles += count << (2 * subdivide);  // each Loop level quadruples the triangles
    if (triangles > kMaxSceneTriangles) {
      fail(key, "the scene would have " + std::to_string(triangles) +
                    " triangles, more than the limit of " + std::to_string(kMaxSceneTriangles) +
                    " (lower subdivide or segments)");
    }
  }

  SceneObject sceneObject(const json& value, const Key& key, std::uint64_t& triangles, bool animated) const {
    requireObject(value, key);
    const json* meshName = find(value, "mesh");
    const json* kind = find(value, "primitive");
    if (meshName && kind) fail(key, "has both \"mesh\" and \"primitive\"; give exactly one");
    if (!meshName && !kind) fail(key, "needs either \"mesh\" or \"primitive\"");
    const json* source = meshName ? meshName : kind;
    const Key sourceKey = key / (meshName ? "mesh" : "primitive");
    if (!source->is_string()) fail(sourceKey, "expected a string, got " + show(*source));
    const std::string name = source->get<std::string>();
    // Validate the keys first so that a typo is reported before a slow mesh load.
    if (meshName)
      checkKeys(value, key, {"mesh", "fit", "scale", "rotate", "translate", "subdivide"});
    const int subdivide = optionalInteger(value, key, "subdivide", 0, 0, 4);

    SceneObject object;
    object.label = key.path + (meshName ? " (mesh " : " (primitive ") + name + ")";
    if (meshName) {
      const fs::path path = resolveMesh(name, sourceKey);
      try {
        object.mesh = readMeshFile(path);
      } catch (const InputError& e) {
        fail(sourceKey, e.what());
      }
      addTriangles(triangles, object.mesh.n_faces(), subdivide, key);
    } else {
      object.mesh = primitive(value, key, name, subdivide, triangles);
    }
    if (subdivide > 0) {
      OpenMesh::Subdivider::Uniform::LoopT<TriMesh> loop;
      loop.attach(object.mesh);
      loop(static_cast<std::size_t>(subdivide));
      loop.detach();
    }
    if (animated) object.local = std::make_shared<const TriMesh>(object.mesh);
    transform(value, key, object);
    return object;
  }

  // fit, then scale, rotate (X, then Y, then Z) and translate.
  void transform(const json& value, const Key& key, SceneObject& object) const {
    TriMesh& mesh = object.mesh;
    glm::mat4 model(1.0f);
    if (const json* fit = find(value, "fit")) {
      const float target = positive(*fit, key / "fit");
      glm::vec3 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
      for (const auto v : mesh.vertices()) {
        const auto& p = mesh.point(v);
        lo = glm::min(lo, glm::vec3(p[0], p[1], p[2]));
        hi = glm::max(hi, glm::vec3(p[0], p[1], p[2]));
      }
      const glm::vec3 extent = hi - lo;
      const float largest = std::max({extent.x, extent.y, extent.z});
      if (!(largest > 0)) fail(key / "fit", "the mesh has zero size");
      model = glm::scale(glm::mat4(1.0f), glm::vec3(target / largest)) *
              glm::translate(glm::mat4(1.0f), -(lo + hi) * 0.5f);
    }
    ObjectPose& pose = object.pose;
    if (const json* s = find(value, "scale")) pose.scale = scaleValue(*s, key / "scale");
    if (const json* r = find(value, "rotate")) pose.rotateDegrees = vec3(*r, key / "rotate");
    if (const json* t = find(value, "translate")) pose.translate = vec3(*t, key / "translate");
    object.fit = model;
    if (!placeMesh(mesh, pose.matrix() * model, mesh))
      fail(key, "transformed coordinates are not finite (scale or translate too large?)");
  }

  glm::vec3 scaleValue(const json& s, const Key& sk) const {
    if (s.is_number()) return glm::vec3(positive(s, sk));
    if (!s.is_array() || s.size() != 3) fail(sk, "expected a positive number or [x, y, z], got " + show(s));
    glm::vec3 scale;
    for (int i = 0; i < 3; ++i) scale[i] = positive(s[i], sk[i]);
    return scale;
  }

  // ---- The animation block (scene/animation.h) ----

  // Reads a list of keys, each with a "frame" in [0, frames − 1], strictly after the
  // previous key's; `fields` reads the rest of a key and returns how many values it gave.
  template <class Fields>
  void keyList(const json& value, const Key& key, int frames, Fields fields) const {
    if (!value.is_array() || value.empty()) fail(key, "expected a non-empty array of keys, got " + show(value));
    int previous = -1;
    for (std::size_t i = 0; i < value.size(); ++i) {
      const Key k = key[i];
      requireObject(value[i], k);
      const int frame = integer(require(value[i], k, "frame"), k / "frame", 0, frames - 1);
      if (frame <= previous)
        fail(k / "frame", "must be after the previous key's frame " + std::to_string(previous) + ", got " +
                              std::to_string(frame) + " (keys sorted, each frame once)");
      previous = frame;
      if (fields(value[i], k, frame) == 0) fail(k, "gives no value besides \"frame\"");
    }
  }

  template <class T>
  static int add(Track<T>& track, int frame, const T& value) {
    track.keys.emplace_back(frame, value);
    return 1;
  }

  Animation animation(const json& value, const Key& key, const CameraDesc& camera, const LightDesc& light,
                      std::size_t objectCount) const {
    requireObject(value, key);
    checkKeys(value, key, {"frames", "fps", "camera", "light", "objects"});
    Animation a;
    a.camera = camera;
    a.light = light;
    a.frames = integer(require(value, key, "frames"), key / "frames", 1, kMaxFrames);
    a.fps = optionalInteger(value, key, "fps", 30, 1, 240);
    if (const json* keys = find(value, "camera")) {
      keyList(*keys, key / "camera", a.frames, [&](const json& k, const Key& kk, int frame) {
        checkKeys(k, kk, {"frame", "eye", "target", "fov_y"});
        int n = 0;
        if (const json* v = find(k, "eye")) n += add(a.cameraEye, frame, vec3(*v, kk / "eye"));
        if (const json* v = find(k, "target")) n += add(a.cameraTarget, frame, vec3(*v, kk / "target"));
        if (find(k, "fov_y")) n += add(a.cameraFovY, frame, optional(k, kk, "fov_y", 45.0, 0.0, 180.0));
        return n;
      });
    }
    if (const json* keys = find(value, "light")) lightKeys(*keys, key / "light", a);
    if (const json* objects = find(value, "objects")) objectTracks(*objects, key / "objects", a, objectCount);
    checkFrames(a, key);
    return a;
  }

  void lightKeys(const json& keys, const Key& key, Animation& a) const {
    const bool spot = a.light.type == LightType::Spot;
    const Names own = spot ? Names{"eye", "target", "fov"} : Names{"direction", "target", "extent"};
    const Names other = spot ? Names{"direction", "extent"} : Names{"eye", "fov"};
    keyList(keys, key, a.frames, [&](const json& k, const Key& kk, int frame) {
      for (const auto& name : other)
        if (k.contains(name))
          fail(kk / name, std::string("a ") + (spot ? "spot" : "directional") + " light has no " + name +
                              " (its keys may give " + join(own) + ")");
      Names allowed = own;
      allowed.push_back("frame");
      checkKeys(k, kk, allowed);
      int n = 0;
      if (const json* v = find(k, "eye")) n += add(a.lightEye, frame, vec3(*v, kk / "eye"));
      if (const json* v = find(k, "target")) n += add(a.lightTarget, frame, vec3(*v, kk / "target"));
      if (find(k, "fov")) n += add(a.lightFov, frame, optional(k, kk, "fov", 45.0, 0.0, 180.0));
      if (const json* v = find(k, "extent")) n += add(a.lightExtent, frame, positive(*v, kk / "extent"));
      if (const json* v = find(k, "direction")) {
        const glm::vec3 unit = direction(*v, kk / "direction");
        // Opposite directions have no one great circle between them.
        if (!a.lightDirection.empty() && glm::dot(a.lightDirection.keys.back().second, unit) < -0.9999f)
          fail(kk / "direction", "is opposite to the previous key's: the great circle between them is undefined");
        n += add(a.lightDirection, frame, unit);
      }
      return n;
    });
  }

  void objectTracks(const json& value, const Key& key, Animation& a, std::size_t objectCount) const {
    if (!value.is_array() || value.empty())
      fail(key, "expected a non-empty array of {\"object\": index, \"keys\": [...]}, got " + show(value));
    for (std::size_t i = 0; i < value.size(); ++i) {
      const Key k = key[i];
      requireObject(value[i], k);
      checkKeys(value[i], k, {"object", "keys"});
      ObjectAnimation track;
      const int last = int(objectCount) - 1;
      track.object = std::size_t(integer(require(value[i], k, "object"), k / "object", 0, last));
      for (const auto& other : a.objects)
        if (other.object == track.object)
          fail(k / "object", "objects[" + std::to_string(track.object) + "] is animated twice");
      keyList(require(value[i], k, "keys"), k / "keys", a.frames, [&](const json& o, const Key& ok, int frame) {
        checkKeys(o, ok, {"frame", "scale", "rotate", "translate"});
        int n = 0;
        if (const json* v = find(o, "scale")) n += add(track.scale, frame, scaleValue(*v, ok / "scale"));
        if (const json* v = find(o, "rotate")) n += add(track.rotate, frame, vec3(*v, ok / "rotate"));
        if (const json* v = find(o, "translate")) n += add(track.translate, frame, vec3(*v, ok / "translate"));
        return n;
      });
      a.objects.push_back(std::move(track));
    }
  }

  // Every frame's camera and light must pass the checks a still scene's do.
  void checkFrames(const Animation& a, const Key& key) const {
    const bool camera = !a.cameraEye.empty() || !a.cameraTarget.empty() || !a.cameraFovY.empty();
    const bool light = !a.lightEye.empty() || !a.lightTarget.empty() || !a.lightDirection.empty() ||
                       !a.lightFov.empty() || !a.lightExtent.empty();
    for (int frame = 0; frame < a.frames && (camera || light); ++frame) {
      try {
        if (camera) checkCamera(cameraAt(a, frame), json::object(), key / "camera");
        if (light) {
          const LightDesc l = lightAt(a, frame);
          if (l.type == LightType::Spot && l.eye == l.target) fail(key / "light", "eye and target meet");
          checkLightTransforms(l, key / "light");
        }
      } catch (const InputError& e) {
        throw InputError(std::string(e.what()) + " (at frame " + std::to_string(frame) + ")");
      }
    }
  }

  // Every frame's placement must be finite, not only the keys': a rotation between two keys
  // turns the mesh, so a coordinate can be largest at no key (a long box swung through
  // 90°). One bound covers every frame: |R·S·q + t| ≤ max|S|·|q| + |t| for each fitted
  // vertex q, where scale and translate, interpolated linearly, never exceed their largest
  // key (or the scene's value where a track has no key). The bound is taken on |fit|·|p|
  // term by term and with room to spare, since the float matrix products add terms of that
  // size before they cancel.
  void checkAnimatedObjects(Animation& a, const std::vector<SceneObject>& objects, const Key& key) const {
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
        fail(key[i], "transformed coordinates could be not finite between keys (beyond " +
                         show(kMaxPlacedCoordinate) + "; scale or translate too large?)");
    }
  }

  fs::path file_;
};

}  // namespace

fs::path assetDirectory() {
  if (const char* dir = std::getenv("TESTBED_ASSET_DIR"); dir && *dir) return dir;
  return TESTBED_DEFAULT_ASSET_DIR;
}

Scene parseScene(const json& document, const fs::path& file) {
  return Parser(file).scene(document);
}

void checkCamera(const CameraDesc& camera, const fs::path& where) {
  Parser(where).checkCamera(camera, json::object(), Key() / "camera");
}

Scene loadScene(const fs::path& file) {
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw InputError(file.string() + ": is a folder, not a scene file");
  return parseScene(readJsonInput(file), file);
}

}  // namespace testbed
