#pragma once
// The checks a scene file's camera gets (scene_values.h), for a camera made otherwise:
// the viewer's scripted moves.
#include <filesystem>

#include "testbed/scene/scene.h"

namespace testbed {

// Throws InputError("<where>: camera.<field>: <problem>") for a camera that would not
// render: degenerate in float precision, or aimed at a target beyond its far plane.
void checkCamera(const CameraDesc& camera, const std::filesystem::path& where);

}  // namespace testbed
