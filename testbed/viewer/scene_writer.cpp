#include "testbed/viewer/scene_writer.h"


#include "testbed/core/error.h"
#include "testbed/io/image_io.h"
#include "testbed/io/json_input.h"
#include "testbed/io/output_files.h"

namespace testbed::viewer {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

void saveSceneWithView(const Scene& scene, const fs::path& destination) {
  // The scene's own file, read as strictly again, then parsed keeping its keys' order.
  const json document = readSceneDocument(scene);
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
