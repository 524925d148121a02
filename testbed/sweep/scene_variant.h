#pragma once
// A scene file with its camera and light replaced: what the viewer's "save scene" writes
// and what the worst-case search writes for each configuration it reports, in a form the
// CLI (`compare --scene`) accepts.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "testbed/scene/scene.h"

namespace testbed {

// `document` (the scene file `source` as parsed JSON) with camera eye/target/up and the
// light's eye/target (spot) or direction/target (directional) set from `camera`/`light`;
// every other key, comments included, is kept. Mesh paths relative to `source`'s folder
// are rewritten relative to `destination`'s folder so the new file finds the same meshes.
// Keys keep the file's order (ordered_json), so the written file reads like the original.
nlohmann::ordered_json sceneWithView(nlohmann::ordered_json document, const std::filesystem::path& source,
                                     const std::filesystem::path& destination, const CameraDesc& camera,
                                     const LightDesc& light);

// The scene file `scene.file`, read as strictly again, keys in the file's order.
nlohmann::ordered_json readSceneDocument(const Scene& scene);

}  // namespace testbed
