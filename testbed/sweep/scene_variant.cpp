#include "testbed/sweep/scene_variant.h"

#include "testbed/io/input_file.h"
#include "testbed/io/json_input.h"

namespace testbed {
namespace {

namespace fs = std::filesystem;
using SceneJson = nlohmann::ordered_json;

// A float written as its double: read back as a float it is the same float, so a
// written scene renders exactly what the in-memory one did.
SceneJson toJson(glm::vec3 v) { return SceneJson::array({double(v.x), double(v.y), double(v.z)}); }

// A mesh entry is an asset name when it has no folder and no extension (as the parser
// resolves it); anything else is a path.
bool isRelativePath(const std::string& mesh) {
  const fs::path path(mesh);
  const bool assetName = mesh.find('/') == std::string::npos && !path.has_extension();
  return !assetName && path.is_relative();
}

fs::path folderOf(const fs::path& file) {
  const fs::path parent = fs::absolute(file).parent_path();
  return parent.lexically_normal();
}

}  // namespace

SceneJson sceneWithView(SceneJson document, const fs::path& source, const fs::path& destination, const CameraDesc& camera,
                   const LightDesc& light) {
  SceneJson& c = document["camera"];
  c["eye"] = toJson(camera.eye);
  c["target"] = toJson(camera.target);
  c["up"] = toJson(camera.up);
  SceneJson& l = document["light"];
  if (light.type == LightType::Spot) {
    l["eye"] = toJson(light.eye);
  } else {
    l["direction"] = toJson(light.direction);
  }
  l["target"] = toJson(light.target);
  for (SceneJson& object : document["objects"]) {
    const auto mesh = object.find("mesh");
    if (mesh == object.end() || !mesh->is_string() || !isRelativePath(mesh->get<std::string>())) continue;
    const fs::path absolute = (folderOf(source) / mesh->get<std::string>()).lexically_normal();
    std::string rewritten = absolute.lexically_relative(folderOf(destination)).generic_string();
    // "bunny" alone would now read as an asset name: keep it a path.
    if (rewritten.find('/') == std::string::npos && !fs::path(rewritten).has_extension()) rewritten = "./" + rewritten;
    *mesh = rewritten;
  }
  return document;
}

SceneJson readSceneDocument(const Scene& scene) {
  const std::string text = readInputFile(scene.file, kMaxJsonInputBytes);
  parseJsonInput(text, scene.file);  // the strict reader's checks and messages
  return SceneJson::parse(text);
}

}  // namespace testbed
