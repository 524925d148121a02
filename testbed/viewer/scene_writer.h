#pragma once
// The viewer's "save scene" button: the scene file it was started with, its camera and
// light replaced by the current ones, written where the user asks, in a form the CLI
// (`render --scene`) accepts.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "testbed/scene/scene.h"

namespace testbed::viewer {

// `document` (the scene file `source` as parsed JSON) with camera eye/target/up and the
// light's eye/target (spot) or direction/target (directional) set from `camera`/`light`;
// every other key, comments included, is kept. Mesh paths relative to `source`'s folder
// are rewritten relative to `destination`'s folder so the new file finds the same meshes.
// Keys keep the file's order (ordered_json), so the written file reads like the original.
nlohmann::ordered_json sceneWithView(nlohmann::ordered_json document, const std::filesystem::path& source,
                             const std::filesystem::path& destination, const CameraDesc& camera,
                             const LightDesc& light);

// Reads scene.file, applies sceneWithView, checks that the result parses as a scene and
// writes it atomically to `destination`. Throws InputError naming the file on failure.
void saveSceneWithView(const Scene& scene, const std::filesystem::path& destination);

}  // namespace testbed::viewer
