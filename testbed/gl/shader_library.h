#pragma once
// GLSL embedded into the binary at build time (cmake/EmbedShader.cmake), keyed by the
// path relative to the repository root. `#include "testbed/glsl/x.glsl"` lines are
// expanded here, each file at most once per shader, so shared GLSL lives in one place.
#include <string>
#include <string_view>
#include <vector>

namespace testbed {

struct ShaderRegistration {
  ShaderRegistration(const char* key, const char* source);
};

// The raw embedded text; throws GlError for an unknown key.
std::string_view embeddedShader(std::string_view key);
// The text with includes expanded. Throws GlError for a missing include or a cycle.
std::string expandShaderSource(std::string_view key);
std::vector<std::string> embeddedShaderKeys();
// The names that GLSL `source` declares `uniform` (comments skipped, preprocessor branches
// all read; uniform blocks are not looked into: the library has none), sorted, unique.
std::vector<std::string> declaredUniforms(std::string_view source);
// Keys registered a second time with other text since the last call (the first text
// stays). Plugins are checked with it, so a plugin cannot silently shadow or lose a shader.
std::vector<std::string> takeShaderConflicts();

}  // namespace testbed
