#pragma once
// Which front-end compiles the testbed's GLSL (docs/portability.md): the driver's own GLSL
// compiler, or Khronos' glslang to SPIR-V loaded through GL_ARB_gl_spirv (gl/spirv.h). A
// record names it ("shader_path"), since two front-ends may compile one source differently.
#include <optional>
#include <string_view>

namespace testbed {

enum class ShaderPath { Glsl, Spirv };

inline std::string_view shaderPathName(ShaderPath path) { return path == ShaderPath::Glsl ? "glsl" : "spirv"; }

// "glsl" or "spirv"; nothing for any other text.
inline std::optional<ShaderPath> parseShaderPath(std::string_view text) {
  if (text == "glsl") return ShaderPath::Glsl;
  if (text == "spirv") return ShaderPath::Spirv;
  return std::nullopt;
}

// From TESTBED_SHADER_PATH: "glsl" (or unset, or empty) or "spirv", read at every program
// build so one process can build both ways. Throws InputError for any other value.
ShaderPath shaderPath();

}  // namespace testbed
