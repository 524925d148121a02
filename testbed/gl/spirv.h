#pragma once
// The second compiler path: the testbed's GLSL compiled by Khronos' reference front-end,
// glslang, to SPIR-V and loaded through GL_ARB_gl_spirv, instead of handed to the driver's
// own GLSL compiler. Two front-ends that must agree on every shader (docs/portability.md).
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "testbed/gl/gl.h"
#include "testbed/gl/shader_path.h"

namespace testbed {

// A SPIR-V program keeps no uniform names (the GL finds none: ARB_gl_spirv, "Uniform
// variables"), so the testbed assigns the locations itself and keeps the table.
struct LocatedUniforms {
  std::vector<std::string> sources;                   // the stages, each declaration located
  std::map<std::string, GLint, std::less<>> locations;  // name → location (an array's first)
};
// Gives every `uniform` declaration of `sources` (the stages of one program, expanded)
// layout(location = N): one location per name across all stages, in order of first
// declaration, so a uniform two stages share has one location and two stages' different
// uniforms never alias; an array gets kArrayLocations of them (glslang refuses a longer
// one as overlapping). Declarations in every preprocessor branch are located (an inactive
// one merely leaves its location unused). Throws GlError naming `what` for a declaration
// with several names or a location of its own, which the path does not handle.
inline constexpr GLint kArrayLocations = 64;
LocatedUniforms locateUniforms(std::vector<std::string> sources, std::string_view what);

// The SPIR-V words of one stage ("vert", "frag" or "comp"), compiled by glslang's library
// (Debian's glslang-dev) as `glslangValidator -G` would: in process, since a process per
// stage costs more than the compile. Throws GlError with glslang's messages, their positions rewritten to the files they
// are about (describeShaderLog with `files`), each line prefixed with `key` otherwise.
// Equal sources are compiled once per process.
std::vector<std::uint32_t> compileToSpirv(std::string_view source, std::string_view stage,
                                          std::string_view key, const std::vector<std::string>& files);

// A shader object of `stage` made from `words` (glShaderBinary, then glSpecializeShader at
// "main"); its compile status says whether the GL accepted them. Throws GlError when the
// context has no GL_ARB_gl_spirv.
GLuint createSpirvShader(GLenum stage, const std::vector<std::uint32_t>& words);

// Called by the context once it is current (glad's core 4.5 loader has no ARB_gl_spirv
// entry point): remembers glSpecializeShaderARB where the GL offers it.
void loadSpirvEntryPoint(void* (*getProc)(const char*));

}  // namespace testbed
