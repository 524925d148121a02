#include "techniques/distance_transform/edtsm_filter_tiles.h"

#include "testbed/render/screen_pass.h"

namespace testbed::distance_transform {
namespace {

constexpr int kKindsUnit = 6;  // texture unit of uTileKinds, clear of the filter's own

}  // namespace

void FilterTiles::begin(glm::ivec2 size, GLuint unit) {
  if (!empty_) empty_ = VertexArray::create();
  const glm::ivec2 tiles = (size + kTile - 1) / kTile;
  if (tiles != tiles_) {
    kinds_ = Texture::create2D(GL_R32UI, tiles.x, tiles.y);
    tiles_ = tiles;
  }
  const GLuint none = 0;
  glClearTexImage(kinds_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
  glBindImageTexture(unit, kinds_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

void FilterTiles::draw(const Program& program, const Framebuffer& target, glm::ivec2 size, glm::ivec2 reach) const {
  beginScreenDraw(program, target, size);
  glBindTextureUnit(kKindsUnit, kinds_.id());
  program.set("uTileKinds", kKindsUnit);
  program.set("uTileReach", (reach + kTile - 1) / kTile);
  program.set("uScreenSize", size);
  glBindVertexArray(empty_.id());
  glDrawArraysInstanced(GL_TRIANGLES, 0, 6, tiles_.x * tiles_.y);
}

}  // namespace testbed::distance_transform
