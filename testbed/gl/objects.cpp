#include "testbed/gl/objects.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>

#include "testbed/core/error.h"

namespace testbed {
namespace {

// One new name from glCreateBuffers, glCreateFramebuffers or glCreateVertexArrays.
GLuint createName(PFNGLCREATEBUFFERSPROC create) {
  GLuint id = 0;
  create(1, &id);
  return id;
}

}  // namespace

GlObject::GlObject(GLuint id, std::uint64_t bytes, Deleter deleter, std::string_view format)
    : id_(id), bytes_(bytes), deleter_(deleter), ledger_(bytes > 0 ? GpuMemoryLedger::current() : nullptr) {
  if (ledger_) {
    resource_ = GpuMemoryLedger::labelled(format);
    ledger_->add(resource_, static_cast<std::int64_t>(bytes_));
  }
  GpuMemoryLedger::addProcessBytes(static_cast<std::int64_t>(bytes_));
}

GlObject::GlObject(GlObject&& other) noexcept
    : id_(other.id_), bytes_(other.bytes_), deleter_(other.deleter_), ledger_(other.ledger_),
      resource_(std::move(other.resource_)) {
  other.id_ = 0;
  other.bytes_ = 0;
  other.ledger_ = nullptr;
}

GlObject& GlObject::operator=(GlObject&& other) noexcept {
  if (this != &other) {
    release();
    id_ = other.id_;
    bytes_ = other.bytes_;
    deleter_ = other.deleter_;
    ledger_ = other.ledger_;
    resource_ = std::move(other.resource_);
    other.id_ = 0;
    other.bytes_ = 0;
    other.ledger_ = nullptr;
  }
  return *this;
}

GlObject::~GlObject() { release(); }

void GlObject::release() {
  if (id_ != 0 && deleter_) deleter_(id_);
  if (ledger_) ledger_->add(resource_, -static_cast<std::int64_t>(bytes_));
  GpuMemoryLedger::addProcessBytes(-static_cast<std::int64_t>(bytes_));
  id_ = 0;
  bytes_ = 0;
  ledger_ = nullptr;
}

// --- Texture ---------------------------------------------------------------------------

Texture::Texture(GLuint id, std::uint64_t bytes, GLenum format, int width, int height, int levels)
    : GlObject(id, bytes, [](GLuint name) { glDeleteTextures(1, &name); }, formatName(format)),
      format_(format), width_(width), height_(height), levels_(levels) {}

Texture Texture::create2D(GLenum internalFormat, int width, int height, int levels) {
  if (width <= 0 || height <= 0) throw GlError("texture size must be positive");
  if (levels <= 0) {
    levels = 1;
    for (int extent = std::max(width, height); extent > 1; extent /= 2) ++levels;
  }
  std::uint64_t bytes = 0;
  for (int level = 0, w = width, h = height; level < levels; ++level) {
    bytes += std::uint64_t(w) * std::uint64_t(h) * bytesPerTexel(internalFormat);
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
  }
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &id);
  glTextureStorage2D(id, levels, internalFormat, width, height);
  Texture texture(id, bytes, internalFormat, width, height, levels);
  checkGlError("allocating a " + std::to_string(width) + "x" + std::to_string(height) + " texture");
  texture.setFilter(GL_NEAREST, GL_NEAREST);
  texture.setWrap(GL_CLAMP_TO_EDGE);
  return texture;
}

Texture Texture::create2DArray(GLenum internalFormat, int width, int height, int layers) {
  if (width <= 0 || height <= 0 || layers <= 0) throw GlError("texture size must be positive");
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &id);
  glTextureStorage3D(id, 1, internalFormat, width, height, layers);
  Texture texture(id, std::uint64_t(width) * std::uint64_t(height) * std::uint64_t(layers) * bytesPerTexel(internalFormat),
                  internalFormat, width, height, 1);
  checkGlError("allocating a " + std::to_string(width) + "x" + std::to_string(height) + "x" +
               std::to_string(layers) + " array texture");
  texture.setFilter(GL_NEAREST, GL_NEAREST);
  texture.setWrap(GL_CLAMP_TO_EDGE);
  return texture;
}

void Texture::setFilter(GLenum minFilter, GLenum magFilter) const {
  glTextureParameteri(id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
  glTextureParameteri(id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
}

void Texture::setWrap(GLenum wrap, const glm::vec4& border) const {
  glTextureParameteri(id(), GL_TEXTURE_WRAP_S, static_cast<GLint>(wrap));
  glTextureParameteri(id(), GL_TEXTURE_WRAP_T, static_cast<GLint>(wrap));
  glTextureParameterfv(id(), GL_TEXTURE_BORDER_COLOR, glm::value_ptr(border));
}

std::vector<float> Texture::readFloats(int components) const {
  static constexpr GLenum kFormats[] = {GL_RED, GL_RG, GL_RGB, GL_RGBA};
  if (components < 1 || components > 4) throw GlError("readFloats: 1 to 4 components");
  const bool depth = format_ == GL_DEPTH_COMPONENT16 || format_ == GL_DEPTH_COMPONENT24 ||
                     format_ == GL_DEPTH_COMPONENT32F;
  std::vector<float> data(std::size_t(width_) * height_ * components);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(id(), 0, depth ? GL_DEPTH_COMPONENT : kFormats[components - 1], GL_FLOAT,
                    static_cast<GLsizei>(data.size() * sizeof(float)), data.data());
  checkGlError("reading back a texture");
  return data;
}

// --- Buffer, Framebuffer, VertexArray --------------------------------------------------

Buffer::Buffer(GLuint id, std::uint64_t bytes)
    : GlObject(id, bytes, [](GLuint name) { glDeleteBuffers(1, &name); }, "buffer") {}

Buffer Buffer::create(std::size_t bytes, const void* data, GLbitfield flags) {
  const GLuint id = createName(glCreateBuffers);
  glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), data, flags);
  Buffer buffer(id, bytes);
  checkGlError("allocating a buffer");
  return buffer;
}

Framebuffer::Framebuffer(GLuint id)
    : GlObject(id, 0, [](GLuint name) { glDeleteFramebuffers(1, &name); }) {}

Framebuffer Framebuffer::create() { return Framebuffer(createName(glCreateFramebuffers)); }

void Framebuffer::attachColor(int index, const Texture& texture, int level) const {
  glNamedFramebufferTexture(id(), GL_COLOR_ATTACHMENT0 + index, texture.id(), level);
}

void Framebuffer::attachColorLayer(int index, const Texture& texture, int layer) const {
  glNamedFramebufferTextureLayer(id(), GL_COLOR_ATTACHMENT0 + index, texture.id(), 0, layer);
}

void Framebuffer::attachDepth(const Texture& texture, int level) const {
  const GLenum format = texture.internalFormat();
  const bool stencil = format == GL_DEPTH24_STENCIL8 || format == GL_DEPTH32F_STENCIL8;
  glNamedFramebufferTexture(id(), stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT, texture.id(), level);
}

void Framebuffer::finish(const std::vector<int>& colorIndices) const {
  std::vector<GLenum> buffers;
  for (int index : colorIndices) buffers.push_back(GL_COLOR_ATTACHMENT0 + index);
  if (buffers.empty()) {
    glNamedFramebufferDrawBuffer(id(), GL_NONE);
    glNamedFramebufferReadBuffer(id(), GL_NONE);
  } else {
    glNamedFramebufferDrawBuffers(id(), static_cast<GLsizei>(buffers.size()), buffers.data());
  }
  const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError("framebuffer incomplete (status " + std::to_string(status) + ")");
}

VertexArray::VertexArray(GLuint id)
    : GlObject(id, 0, [](GLuint name) { glDeleteVertexArrays(1, &name); }) {}

VertexArray VertexArray::create() { return VertexArray(createName(glCreateVertexArrays)); }

void VertexArray::setVertexBuffer(const Buffer& buffer, GLsizei stride) const {
  glVertexArrayVertexBuffer(id(), 0, buffer.id(), 0, stride);
}

void VertexArray::setFloatAttribute(GLuint index, GLint components, std::size_t offset) const {
  glEnableVertexArrayAttrib(id(), index);
  glVertexArrayAttribFormat(id(), index, components, GL_FLOAT, GL_FALSE, GLuint(offset));
  glVertexArrayAttribBinding(id(), index, 0);
}

// --- Program ---------------------------------------------------------------------------

namespace {

bool isImage(GLenum type) { return type >= GL_IMAGE_1D && type <= GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY; }

}  // namespace

Program::Program(GLuint id, std::string name, std::vector<std::string> declared, std::optional<Locations> spirvLocations)
    : GlObject(id, 0, [](GLuint program) { glDeleteProgram(program); }),
      name_(std::move(name)),
      declared_(std::move(declared)) {
  if (!spirvLocations) return;
  // Keep only the active ones: setting a dropped uniform's location would be a GL error.
  spirvLocations_.emplace();
  for (const Active& uniform : activeUniforms())
    for (const auto& [uniformName, at] : *spirvLocations)
      if (at == uniform.location) spirvLocations_->emplace(uniformName, at);
}

GLint Program::location(const char* name) const {
  if (!spirvLocations_) return glGetUniformLocation(id(), name);
  const auto found = spirvLocations_->find(std::string_view(name));
  return found == spirvLocations_->end() ? -1 : found->second;
}

GLint Program::checkedLocation(const char* name) const {
  const GLint at = location(name);
  if (at < 0 && !std::binary_search(declared_.begin(), declared_.end(), std::string_view(name)))
    throw std::logic_error(name_ + ": no uniform named " + name + " in its sources (misspelt?)");
  const auto slot = std::lower_bound(setLocations_.begin(), setLocations_.end(), at);
  if (at >= 0 && (slot == setLocations_.end() || *slot != at)) setLocations_.insert(slot, at);
  return at;
}

std::vector<Program::Active> Program::activeUniforms() const {
  GLint count = 0;
  glGetProgramInterfaceiv(id(), GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  GLint longest = 0;
  glGetProgramInterfaceiv(id(), GL_UNIFORM, GL_MAX_NAME_LENGTH, &longest);
  std::vector<Active> active;
  std::string name(std::size_t(std::max(longest, 1)), '\0');
  for (GLint i = 0; i < count; ++i) {
    // Block members and built-ins have location -1; an array reports its first element's.
    static constexpr GLenum kProperties[] = {GL_LOCATION, GL_TYPE};
    GLint values[2] = {-1, 0};
    glGetProgramResourceiv(id(), GL_UNIFORM, GLuint(i), 2, kProperties, 2, nullptr, values);
    if (values[0] < 0) continue;
    GLsizei length = 0;
    if (!spirvLocations_) glGetProgramResourceName(id(), GL_UNIFORM, GLuint(i), GLsizei(name.size()), &length, name.data());
    const std::string uniform = name.substr(0, std::size_t(length));
    active.push_back({uniform.substr(0, uniform.find('[')), values[0], GLenum(values[1])});
  }
  if (spirvLocations_)
    for (Active& uniform : active)
      for (const auto& [uniformName, at] : *spirvLocations_)
        if (at == uniform.location) uniform.name = uniformName;
  return active;
}

std::vector<std::string> Program::unsetUniforms() const {
  std::vector<std::string> unset;
  for (const Active& uniform : activeUniforms()) {
    // Images take their unit from layout(binding = N), never from set().
    if (isImage(uniform.type)) continue;
    if (!std::binary_search(setLocations_.begin(), setLocations_.end(), uniform.location)) unset.push_back(uniform.name);
  }
  std::sort(unset.begin(), unset.end());
  return unset;
}

void Program::use() const { glUseProgram(id()); }

UnsetUniformPolicy unsetUniformPolicy() {
  static const UnsetUniformPolicy policy = [] {
    const char* value = std::getenv("TESTBED_UNSET_UNIFORMS");
    return value && std::string_view(value) == "error" ? UnsetUniformPolicy::Error : UnsetUniformPolicy::Warn;
  }();
  return policy;
}
void Program::set(const char* name, int v) const { glProgramUniform1i(id(), checkedLocation(name), v); }
void Program::set(const char* name, float v) const { glProgramUniform1f(id(), checkedLocation(name), v); }
void Program::set(const char* name, const glm::vec2& v) const {
  glProgramUniform2fv(id(), checkedLocation(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec3& v) const {
  glProgramUniform3fv(id(), checkedLocation(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::vec4& v) const {
  glProgramUniform4fv(id(), checkedLocation(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const glm::ivec2& v) const {
  glProgramUniform2iv(id(), checkedLocation(name), 1, glm::value_ptr(v));
}
void Program::set(const char* name, const std::vector<float>& v) const {
  glProgramUniform1fv(id(), checkedLocation(name), GLsizei(v.size()), v.data());
}
void Program::set(const char* name, const glm::mat4& v) const {
  glProgramUniformMatrix4fv(id(), checkedLocation(name), 1, GL_FALSE, glm::value_ptr(v));
}

void checkGlError(std::string_view what) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR)
    throw GlError("GL error " + std::to_string(error) + " while " + std::string(what));
}

}  // namespace testbed
