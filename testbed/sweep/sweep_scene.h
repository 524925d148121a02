#pragma once
// Scenes as a sweep cell asks for them: the scene file, optionally with every mesh object
// Loop-subdivided N times (the polygon-count axis of the papers' scaling tables).
#include <filesystem>
#include <optional>

#include "testbed/scene/scene.h"

namespace testbed {

// Throws InputError naming the file and key, as loadScene does.
Scene loadSweepScene(const std::filesystem::path& file, std::optional<int> subdivide);

}  // namespace testbed
