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
// The text with includes expanded, and `#line <line> <file>` directives around each
// included file (and after the #version line, where Program inserts its defines), so the
// compiler counts every file's lines as its author does: the compiler's messages cite
// source-string number i for files[i], files[0] being `key`. Throws GlError for a missing
// include or a cycle.
struct ExpandedShader {
  std::string text;
  std::vector<std::string> files;
};
ExpandedShader expandShader(std::string_view key);
std::string expandShaderSource(std::string_view key);  // expandShader(key).text
// A compiler's info log made readable: one line per message, its "source:line" position
// (Mesa's "2:71(5): error: ...", NVIDIA's "2(71) : error ...", AMD's "ERROR: 2:71: ...")
// rewritten as "file:71:5: error: ..." (the file from the line number, lines of file i
// counting from i·100000, else files[source]); other lines kept, prefixed with
// `fallback` ("techniques/pcf/pcf_visibility.frag: ..."); blank lines dropped.
std::string describeShaderLog(std::string_view log, const std::vector<std::string>& files, std::string_view fallback);
std::vector<std::string> embeddedShaderKeys();
// `source` with every comment blanked to spaces, newlines kept: the same length, so an
// offset found in it is an offset in `source`, and a `uniform` in a comment is not seen.
std::string blankComments(std::string_view source);
// Each `uniform ...;` declaration of comment-blanked `code` (uniform blocks are skipped):
// where its keyword starts, and its text between the keyword and the ';'.
struct UniformDeclaration {
  std::size_t at;
  std::string_view text;
};
std::vector<UniformDeclaration> uniformDeclarations(std::string_view code);
// The names that GLSL `source` declares `uniform` (comments skipped, preprocessor branches
// all read; uniform blocks are not looked into: the library has none), sorted, unique.
std::vector<std::string> declaredUniforms(std::string_view source);
// Keys registered a second time with other text since the last call (the first text
// stays). Plugins are checked with it, so a plugin cannot silently shadow or lose a shader.
std::vector<std::string> takeShaderConflicts();

// Where the environment variable TESTBED_SHADER_DUMP names a folder, writes `source` (a
// stage's final text, as handed to the GL: includes expanded, #line directives and defines
// in) there as "<key, '/' → '_'>.<16 hex digits of its FNV-1a hash>.<stage>", `stage` being
// "vert", "frag" or "comp" — the extension glslangValidator picks the stage by. Equal
// sources land on one file, so every variant a run builds is there once
// (tests/glslang_portability_test.py feeds them to Khronos' reference compiler). Written
// to a temporary name and renamed, so processes dumping at once never see half a file.
// Does nothing when the variable is unset or empty; throws GlError if the write fails.
void dumpFinalShader(std::string_view key, std::string_view stage, std::string_view source);

}  // namespace testbed
