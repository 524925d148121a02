#include "techniques/distance_transform/edtsm_filter_tiles.h"

#include "testbed/glsl/units.h"

namespace testbed::distance_transform {
namespace {

constexpr GLuint kArguments = 6;  // two indirect dispatches' (x, y, z) ahead of the lists

}  // namespace

void FilterTiles::begin(glm::ivec2 size) {
  const glm::ivec2 tiles = (size + kTile - 1) / kTile;
  if (tiles != tiles_) {
    GpuMemoryLedger::Label label("filter-tiles", ResourceRole::Device);
    kinds_ = Texture::create2D(GL_R32UI, tiles.x, tiles.y);
    lists_ = Buffer::create((kArguments + 2 * std::size_t(tiles.x) * std::size_t(tiles.y)) * sizeof(GLuint), nullptr,
                            GL_DYNAMIC_STORAGE_BIT);
    tiles_ = tiles;
  }
  const GLuint none = 0;
  glClearTexImage(kinds_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
  glBindImageTexture(kTileKindsImageUnit, kinds_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

void FilterTiles::findTiles(int radius) {
  if (!listProgram_) listProgram_ = Program::compute("techniques/distance_transform/edtsm_filter_tiles.comp");
  const GLuint empty[kArguments] = {0, 1, 1, 0, 1, 1};
  glNamedBufferSubData(lists_.id(), 0, sizeof(empty), empty);
  const int reach = (radius + kTile - 1) / kTile;
  listProgram_.use();
  glBindTextureUnit(kTileKindsTextureUnit, kinds_.id());
  listProgram_.set("uTileKinds", kTileKindsTextureUnit);
  listProgram_.set("uRowReach", glm::ivec2(reach, 0));
  listProgram_.set("uColumnReach", glm::ivec2(reach));
  listProgram_.set("uListLength", tiles_.x * tiles_.y);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBufferBinding, lists_.id());
  glDispatchCompute(GLuint((tiles_.x * tiles_.y + 63) / 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
}

void FilterTiles::dispatch(const Program& program, const Texture& target, GLenum format, bool columns) const {
  program.use();
  program.set("uListOffset", int(kArguments) + (columns ? tiles_.x * tiles_.y : 0));
  program.set("uTileColumns", tiles_.x);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBufferBinding, lists_.id());
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, lists_.id());
  glBindImageTexture(kEdtsmOutputImageUnit, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glDispatchComputeIndirect(GLintptr(columns ? 3 * sizeof(GLuint) : 0));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
  glBindImageTexture(kEdtsmOutputImageUnit, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, format);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileListBufferBinding, 0);
}

}  // namespace testbed::distance_transform
