#pragma once
// Which front-end compiles the testbed's GLSL (docs/portability.md): the driver's own GLSL
// compiler, or Khronos' glslang to SPIR-V loaded through GL_ARB_gl_spirv (gl/spirv.h). A
// record names it ("shader_path"), since two front-ends may compile one source differently.
#include <cstdlib>
#include <optional>
#include <string>
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

inline constexpr const char* kShaderPathVariable = "TESTBED_SHADER_PATH";

// From TESTBED_SHADER_PATH: "glsl" (or unset, or empty) or "spirv", read at every program
// build so one process can build both ways. Throws InputError for any other value.
ShaderPath shaderPath();

// Sets TESTBED_SHADER_PATH to `value` for a scope: every program built meanwhile takes that
// path (the stability check renders both ways in one process; tests also set bad values).
// The previous value, or its absence, comes back at the end.
class ShaderPathScope {
 public:
  explicit ShaderPathScope(ShaderPath path) : ShaderPathScope(shaderPathName(path)) {}
  explicit ShaderPathScope(std::string_view value) {
    if (const char* current = std::getenv(kShaderPathVariable)) previous_ = current;
    setenv(kShaderPathVariable, std::string(value).c_str(), 1);
  }
  ~ShaderPathScope() {
    if (previous_) setenv(kShaderPathVariable, previous_->c_str(), 1);
    else unsetenv(kShaderPathVariable);
  }
  ShaderPathScope(const ShaderPathScope&) = delete;
  ShaderPathScope& operator=(const ShaderPathScope&) = delete;

 private:
  std::optional<std::string> previous_;
};

}  // namespace testbed
