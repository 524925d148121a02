#pragma once
// Reading a scene file's "animation" block (scene/animation.h; format: docs/scenes.md):
// its keys, each checked as the still scene's values are (scene_values.h), and every
// frame's camera, light and object placement checked between the keys.
#include <cstddef>
#include <vector>

#include "testbed/io/json_reader.h"
#include "testbed/scene/animation.h"
#include "testbed/scene/scene.h"

namespace testbed::scene_file {

// The block at `block`, for a scene of `camera`, `light` and `objectCount` objects.
Animation readAnimation(const JsonField& block, const CameraDesc& camera, const LightDesc& light,
                        std::size_t objectCount);

// Once the objects are read: takes each animated object's base pose, and refuses a track
// whose placement could leave float range at some frame. `block` is the same block.
void checkAnimatedObjects(Animation& animation, const std::vector<SceneObject>& objects, const JsonField& block);

}  // namespace testbed::scene_file
