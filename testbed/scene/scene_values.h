#pragma once
// The value checks of a scene file: numbers as the renderer keeps them (floats), their
// ranges, and the precision checks of the camera and the light, whose values can pass as
// numbers yet degenerate in float arithmetic. Values come through the checked JSON reader
// (io/json_reader.h), so a fault is one line naming the file and the key path. Shared by
// the scene reader (scene_parser.cpp) and the animation block's (animation_reader.cpp).
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/io/json_reader.h"
#include "testbed/scene/scene.h"

namespace testbed::scene_file {

using Names = std::vector<std::string>;

inline constexpr double kUnbounded = std::numeric_limits<double>::infinity();

std::string showNumber(double value);  // "0.1", "1e+07": as messages print numbers
std::string joinNames(const Names& names);

// Refuses unknown keys of a scene object; "comment" (a string) is allowed everywhere.
void allowKeys(const JsonField& object, Names allowed);

// A finite number a float holds (1e300 would silently become infinity there).
double floatNumber(const JsonField& value);
// Range checks run on the float that is kept, so that 1e-50 cannot pass as "> 0".
float positive(const JsonField& value);
// Within [lo, hi) (or (lo, hi) when loOpen); hi may be kUnbounded.
float bounded(const JsonField& value, double lo, double hi, bool loOpen);
// `object[name]` checked as bounded(), or `fallback` where the key is absent.
float optionalBounded(const JsonField& object, const char* name, double fallback, double lo, double hi,
                      bool loOpen = true);
int optionalInteger(const JsonField& object, const char* name, int fallback, int lo, int hi);

glm::vec3 vec3(const JsonField& value);       // [x, y, z] of floats
glm::vec3 direction(const JsonField& value);  // any non-zero vector, made unit
glm::vec3 scaleValue(const JsonField& value);  // a positive number or [x, y, z] of them
// An array that is not empty: "expected <form>, got ..." otherwise.
std::size_t nonEmptyArray(const JsonField& value, const std::string& form);

// "near" and "far" of a camera or spot light, far beyond near.
void nearFar(const JsonField& object, float& nearPlane, float& farPlane);

// A camera that would not render: degenerate in float precision, or aimed at a target
// beyond its far plane. `given` is the camera's object as written (for "got ..." as the
// file has it, and for the key path of messages); it may be an empty object.
void checkCamera(const CameraDesc& camera, const JsonField& given);
// The light's values must make a finite, invertible shadow-map transform in float.
void checkLightTransforms(LightDesc light, const JsonField& at);

}  // namespace testbed::scene_file
