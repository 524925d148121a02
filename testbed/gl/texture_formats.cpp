// What objects.h says of formats and roles without making any GL call, so the readers
// that name them (declarations, records) link without a GL context or the shader compilers.
#include <string>

#include "testbed/core/error.h"
#include "testbed/gl/objects.h"

namespace testbed {
namespace {

struct FormatInfo {
  GLenum format;
  std::string_view name;
  std::uint32_t bytes;  // per texel
};

const FormatInfo& formatInfo(GLenum format) {
  static constexpr FormatInfo kFormats[] = {
      {GL_R8, "R8", 1}, {GL_RG8, "RG8", 2}, {GL_R16, "R16", 2}, {GL_R16F, "R16F", 2},
      {GL_DEPTH_COMPONENT16, "DEPTH_COMPONENT16", 2}, {GL_RGBA8, "RGBA8", 4}, {GL_RG16, "RG16", 4},
      {GL_RG16F, "RG16F", 4}, {GL_R32F, "R32F", 4}, {GL_R32UI, "R32UI", 4}, {GL_R32I, "R32I", 4},
      {GL_RGB10_A2, "RGB10_A2", 4}, {GL_R11F_G11F_B10F, "R11F_G11F_B10F", 4},
      {GL_DEPTH_COMPONENT24, "DEPTH_COMPONENT24", 4}, {GL_DEPTH_COMPONENT32F, "DEPTH_COMPONENT32F", 4},
      {GL_DEPTH24_STENCIL8, "DEPTH24_STENCIL8", 4}, {GL_RGBA16, "RGBA16", 8}, {GL_RGBA16F, "RGBA16F", 8},
      {GL_RG32F, "RG32F", 8}, {GL_RG32UI, "RG32UI", 8}, {GL_RG32I, "RG32I", 8},
      {GL_DEPTH32F_STENCIL8, "DEPTH32F_STENCIL8", 8}, {GL_RGBA32F, "RGBA32F", 16}, {GL_RGBA32UI, "RGBA32UI", 16},
      {GL_RGBA32I, "RGBA32I", 16}};
  for (const FormatInfo& info : kFormats)
    if (info.format == format) return info;
  throw GlError("unsupported internal format " + std::to_string(format));
}

}  // namespace

std::string_view roleName(ResourceRole role) { return role == ResourceRole::Paper ? "paper" : "device"; }

// 24-bit depth is padded to 32 bits by every driver we know, so it counts 4.
std::uint32_t bytesPerTexel(GLenum format) { return formatInfo(format).bytes; }
std::string_view formatName(GLenum format) { return formatInfo(format).name; }

}  // namespace testbed
