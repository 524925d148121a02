#include "techniques/distance_transform/feature_transform.h"

#include <string>

#include "testbed/core/error.h"
#include "testbed/glsl/units.h"

namespace testbed {
namespace {

constexpr int kGroupSize = 64;  // local_size_x of both shaders

GLuint groupsFor(int invocations) { return GLuint((invocations + kGroupSize - 1) / kGroupSize); }

}  // namespace

void FeatureTransformPass::run(const Texture& seeds, glm::ivec2 size) {
  prepare(size);
  if (size.x > seeds.width() || size.y > seeds.height())
    throw GlError("feature transform: the seed texture is smaller than the requested size");
  if (!rowsProgram_) {
    rowsProgram_ = Program::compute("techniques/distance_transform/feature_transform_rows.comp");
    columnsProgram_ = Program::compute("techniques/distance_transform/feature_transform_columns.comp");
  }
  GpuMemoryLedger::Label label("edt-scratch", ResourceRole::Paper);
  if (nearest_.width() != size.x || nearest_.height() != size.y) nearest_ = Texture::create2D(GL_RG32I, size.x, size.y);
  // The seeds may have just been written by an image store.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindTextureUnit(kEdtSeedsTextureUnit, seeds.id());
  rowsProgram_.use();
  rowsProgram_.set("uSeeds", kEdtSeedsTextureUnit);
  rows(rowsProgram_);
  glBindImageTexture(kEdtsmOutputImageUnit, nearest_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32I);
  columns(columnsProgram_);
  glBindImageTexture(kEdtsmOutputImageUnit, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG32I);
  checkGlError("feature transform");
}

void FeatureTransformPass::run(glm::ivec2 size, const Program& rowsProgram, const Program& columnsProgram,
                               const std::function<void()>& between) {
  prepare(size);
  rows(rowsProgram);
  if (between) between();
  columns(columnsProgram);
  checkGlError("feature transform");
}

void FeatureTransformPass::prepare(glm::ivec2 size) {
  if (size.x <= 0 || size.y <= 0 || size.x > kMaxExtent || size.y > kMaxExtent)
    throw GlError("feature transform: size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                  " out of range (1 to " + std::to_string(kMaxExtent) + " a side)");
  if (size != size_) {
    // Allocated here, not at construction, so they are booked in the ledger current while
    // the technique renders.
    GpuMemoryLedger::Label label("edt-scratch", ResourceRole::Paper);
    rowNearest_ = Texture::create2D(GL_R32I, size.x, size.y);
    envelope_ = Texture::create2D(GL_RG32I, size.x, size.y);
    size_ = size;
  }
}

void FeatureTransformPass::rows(const Program& rowsProgram) {
  rowsProgram.use();
  rowsProgram.set("uSize", size_);
  glBindImageTexture(kRowNearestImageUnit, rowNearest_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32I);
  glDispatchCompute(groupsFor(size_.y), 1, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void FeatureTransformPass::columns(const Program& columnsProgram) {
  columnsProgram.use();
  columnsProgram.set("uSize", size_);
  glBindImageTexture(kRowNearestImageUnit, rowNearest_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32I);
  glBindImageTexture(kEnvelopeImageUnit, envelope_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32I);
  glDispatchCompute(groupsFor(size_.x), 1, 1);
  // Whatever reads the result next: a texel fetch, an image load, a copy, a blit or a
  // read-back.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
  glBindImageTexture(kRowNearestImageUnit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32I);
  glBindImageTexture(kEnvelopeImageUnit, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RG32I);
}

std::vector<glm::ivec2> FeatureTransformPass::readNearest() const {
  std::vector<glm::ivec2> texels(std::size_t(size_.x) * std::size_t(size_.y));
  if (texels.empty()) return texels;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(nearest_.id(), 0, GL_RG_INTEGER, GL_INT, GLsizei(texels.size() * sizeof(glm::ivec2)),
                    texels.data());
  checkGlError("reading back the feature transform");
  return texels;
}

}  // namespace testbed
