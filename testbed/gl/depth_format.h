#pragma once
// Shadow-map depth storage: 16-bit (the papers' default), 24-bit, 32-bit float.
#include <string>
#include <string_view>

#include "testbed/gl/gl.h"

namespace testbed {

enum class DepthFormat { D16, D24, D32F };

// "16", "24", "32f"; throws InputError for anything else.
DepthFormat parseDepthFormat(std::string_view text);
std::string depthFormatName(DepthFormat format);
GLenum depthInternalFormat(DepthFormat format);

}  // namespace testbed
