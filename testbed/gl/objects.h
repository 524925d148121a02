#pragma once
// Move-only RAII owners of GL objects. Every allocation is booked in a GpuMemoryLedger so
// a technique's memory footprint is measured from what it really allocates, never typed in.
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include <glm/glm.hpp>

#include "testbed/gl/gl.h"
#include "testbed/gl/memory_ledger.h"

namespace testbed {

// The name of a sized internal format as GL spells it without GL_ ("RGBA32F").
std::string_view formatName(GLenum internalFormat);
// Bytes per texel of a sized internal format as the hardware stores it (24-bit depth is
// padded to 32 bits by every driver we know, so it counts 4).
std::uint32_t bytesPerTexel(GLenum internalFormat);

// Shared base: owns the name and its booked bytes.
class GlObject {
 public:
  GlObject() = default;
  GlObject(GlObject&& other) noexcept;
  GlObject& operator=(GlObject&& other) noexcept;
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  std::uint64_t bytes() const { return bytes_; }

 protected:
  using Deleter = void (*)(GLuint);
  // `format`: what the ledger's split names it by (formatName, or "buffer").
  GlObject(GLuint id, std::uint64_t bytes, Deleter deleter, std::string_view format = {});
  ~GlObject();
  void release();

 private:
  GLuint id_ = 0;
  std::uint64_t bytes_ = 0;
  Deleter deleter_ = nullptr;
  GpuMemoryLedger* ledger_ = nullptr;
  GpuMemoryLedger::Resource resource_;  // where the ledger booked the bytes
};

class Texture : public GlObject {
 public:
  Texture() = default;
  // Immutable 2D storage; levels = 0 means a full mip chain.
  static Texture create2D(GLenum internalFormat, int width, int height, int levels = 1);
  // Immutable 2D array storage, one level (a pass's layered scratch; readFloats is for 2D).
  static Texture create2DArray(GLenum internalFormat, int width, int height, int layers);

  int width() const { return width_; }
  int height() const { return height_; }
  int levels() const { return levels_; }
  GLenum internalFormat() const { return format_; }

  void setFilter(GLenum minFilter, GLenum magFilter) const;
  void setWrap(GLenum wrap, const glm::vec4& border = glm::vec4(0)) const;
  // Reads level 0 as floats (`components` of GL_RED/GL_RG/GL_RGB/GL_RGBA), rows bottom-up.
  std::vector<float> readFloats(int components) const;

 private:
  Texture(GLuint id, std::uint64_t bytes, GLenum format, int width, int height, int levels);
  GLenum format_ = 0;
  int width_ = 0, height_ = 0, levels_ = 0;
};

class Buffer : public GlObject {
 public:
  Buffer() = default;
  static Buffer create(std::size_t bytes, const void* data, GLbitfield flags = 0);

 private:
  Buffer(GLuint id, std::uint64_t bytes) ;
};

class Framebuffer : public GlObject {
 public:
  Framebuffer() = default;
  static Framebuffer create();
  void attachColor(int index, const Texture& texture, int level = 0) const;
  // One layer of an array texture (Texture::create2DArray) at colour attachment `index`.
  void attachColorLayer(int index, const Texture& texture, int layer) const;
  // At the depth-stencil attachment for a format with stencil.
  void attachDepth(const Texture& texture, int level = 0) const;
  // Sets the draw buffers to the attached color indices and checks completeness.
  void finish(const std::vector<int>& colorIndices) const;

 private:
  explicit Framebuffer(GLuint id);
};

class VertexArray : public GlObject {
 public:
  VertexArray() = default;
  static VertexArray create();
  // Binding 0 reads `buffer`, one vertex every `stride` bytes.
  void setVertexBuffer(const Buffer& buffer, GLsizei stride) const;
  // Attribute `index` (binding 0): `components` floats at `offset` in the vertex, e.g.
  // offsetof(Vertex, normal).
  void setFloatAttribute(GLuint index, GLint components, std::size_t offset) const;

 private:
  explicit VertexArray(GLuint id);
};

// A linked program built from embedded shader sources (keys of the shader library).
// set() throws std::logic_error naming the program and the uniform when no source of the
// program declares that uniform (a misspelt name would otherwise be silently ignored); a
// uniform that is declared but compiled away (unused in this variant) is ignored.
//
// A uniform the program uses and nobody ever set reads 0, which renders garbage without a
// word (a forgotten light parameter). requireUniformsSet() (render/uniform_check.h) runs
// right before the draws of every screen pass, the G-buffer and the shadow map: every
// active uniform (images aside: their unit is their layout binding) must have been set
// through set(); a miss warns on stderr, or is a std::logic_error where the environment
// has TESTBED_UNSET_UNIFORMS=error (unsetUniformPolicy()), as the test binary sets it.
class Program : public GlObject {
 public:
  Program() = default;
  // `defines` is prepended after #version (e.g. "#define KERNEL 3\n").
  static Program graphics(std::string_view vertexKey, std::string_view fragmentKey,
                          std::string_view defines = {});
  static Program compute(std::string_view computeKey, std::string_view defines = {});

  // -1 for a uniform the program does not have (or the compiler dropped). Built through
  // SPIR-V (gl/spirv.h), the program has no uniform names: its own table answers.
  GLint location(const char* name) const;
  void set(const char* name, int value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const glm::vec2& value) const;
  void set(const char* name, const glm::vec3& value) const;
  void set(const char* name, const glm::vec4& value) const;
  void set(const char* name, const glm::ivec2& value) const;
  void set(const char* name, const glm::mat4& value) const;
  void set(const char* name, const std::vector<float>& values) const;  // a float array
  // glUseProgram (uniforms may be set after it: the check above runs at the draw).
  void use() const;
  // The active uniforms never set through set(), sorted ("uLightFar").
  std::vector<std::string> unsetUniforms() const;

 private:
  struct Stage;
  // Compiles and links `stages` the way shaderPath() says; `name` for messages.
  static Program build(std::vector<Stage> stages, std::string_view name);
  using Locations = std::map<std::string, GLint, std::less<>>;
  // `spirvLocations`: the table of a program built through SPIR-V (all its uniforms').
  Program(GLuint id, std::string name, std::vector<std::string> declared,
          std::optional<Locations> spirvLocations = std::nullopt);
  // location(), or the logic_error above.
  GLint checkedLocation(const char* name) const;
  // The active uniforms as (name, location, type): the GL's names, or for SPIR-V the table's.
  struct Active {
    std::string name;
    GLint location;
    GLenum type;
  };
  std::vector<Active> activeUniforms() const;

  std::string name_;                   // the fragment or compute shader's key
  std::vector<std::string> declared_;  // uniform names of its sources, sorted
  // SPIR-V only: name → location of the active uniforms, as the build assigned them.
  std::optional<Locations> spirvLocations_;
  mutable std::vector<GLint> setLocations_;  // every location set() wrote, sorted
};

enum class UnsetUniformPolicy { Warn, Error };
// From TESTBED_UNSET_UNIFORMS ("error" or "warn"; unset: warn), read once.
UnsetUniformPolicy unsetUniformPolicy();

// Throws GlError naming `what` if the GL error flag is set.
void checkGlError(std::string_view what);

}  // namespace testbed
