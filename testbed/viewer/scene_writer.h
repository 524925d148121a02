#pragma once
// The viewer's "save scene" button: the scene file it was started with, its camera and
// light replaced by the current ones, written where the user asks, in a form the CLI
// (`render --scene`) accepts.
#include <filesystem>

#include <nlohmann/json.hpp>

#include "testbed/scene/scene.h"
#include "testbed/sweep/scene_variant.h"

namespace testbed::viewer {

using testbed::sceneWithView;  // sweep/scene_variant.h

// Reads scene.file, applies sceneWithView, checks that the result parses as a scene and
// writes it atomically to `destination`. Throws InputError naming the file on failure.
void saveSceneWithView(const Scene& scene, const std::filesystem::path& destination);

}  // namespace testbed::viewer
