#include "testbed/viewer/scene_writer.h"


#include "testbed/core/error.h"
#include "testbed/io/image_io.h"
#include "testbed/io/json_input.h"

namespace testbed::viewer {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

json toJson(glm::vec3 v) { return json::array({v.x, v.y, v.z}); }

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

json sceneWithView(json document, const fs::path& source, const fs::path& destination, const CameraDesc& camera,
                   const LightDesc& light) {
  json& c = document["camera"];
  c["eye"] = toJson(camera.eye);
  c["target"] = toJson(camera.target);
  c["up"] = toJson(camera.up);
  json& l = document["light"];
  if (light.type == LightType::Spot) {
    l["eye"] = toJson(light.eye);
  } else {
    l["direction"] = toJson(light.direction);
  }
  l["target"] = toJson(light.target);
  for (json& object : document["objects"]) {
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

void saveSceneWithView(const Scene& scene, const fs::path& destination) {
  // The scene's own file, read as strictly again, then parsed keeping its keys' order.
  const std::string text = readInputFile(scene.file, kMaxJsonInputBytes);
  parseJsonInput(text, scene.file);
  const json document = json::parse(text);
  const json written = sceneWithView(document, scene.file, destination, scene.camera, scene.light);
  fs::path folder = destination.parent_path();
  if (folder.empty()) folder = ".";
  OutputFiles files(folder);
  files.writeText(destination.filename().string(), written.dump(2) + "\n");  // creates the folder
  // The CLI must accept what we write: parsed from where it lands (relative mesh paths
  // resolve through that folder); an error leaves nothing behind.
  parseScene(nlohmann::json::parse(written.dump()), destination);
  files.commit();
}

}  // namespace testbed::viewer
