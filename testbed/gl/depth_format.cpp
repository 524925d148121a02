#include "testbed/gl/depth_format.h"

#include "testbed/core/error.h"

namespace testbed {

DepthFormat parseDepthFormat(std::string_view text) {
  if (text == "16") return DepthFormat::D16;
  if (text == "24") return DepthFormat::D24;
  if (text == "32f" || text == "32F") return DepthFormat::D32F;
  throw InputError("--depth-format: expected 16, 24 or 32f, got '" + std::string(text) + "'");
}

std::string depthFormatName(DepthFormat format) {
  switch (format) {
    case DepthFormat::D16: return "16";
    case DepthFormat::D24: return "24";
    case DepthFormat::D32F: return "32f";
  }
  return "?";
}

GLenum depthInternalFormat(DepthFormat format) {
  switch (format) {
    case DepthFormat::D16: return GL_DEPTH_COMPONENT16;
    case DepthFormat::D24: return GL_DEPTH_COMPONENT24;
    case DepthFormat::D32F: return GL_DEPTH_COMPONENT32F;
  }
  return GL_DEPTH_COMPONENT16;
}

}  // namespace testbed
