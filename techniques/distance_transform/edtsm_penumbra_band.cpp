#include "techniques/distance_transform/edtsm_penumbra_band.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "testbed/glsl/units.h"

namespace testbed::distance_transform {

void PenumbraBand::begin(glm::ivec2 size) {
  const glm::ivec2 tiles = (size + kTile - 1) / kTile;
  if (size != size_) {
    GpuMemoryLedger::Label label("penumbra-band", ResourceRole::Device);
    seeds_ = Texture::create2D(GL_R32UI, tiles.x, tiles.y);
    minDepth_ = Texture::create2D(GL_R32UI, tiles.x, tiles.y);
    runs_ = Buffer::create(std::size_t(tiles.x) * std::size_t(tiles.y + 1) * 4 * sizeof(GLint), nullptr);
    size_ = size;
    tiles_ = tiles;
  }
  const GLuint none = 0, noDepth = 0xFFFFFFFFu;
  glClearTexImage(seeds_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
  glClearTexImage(minDepth_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &noDepth);
  glBindImageTexture(kTileSeedsImageUnit, seeds_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindImageTexture(kTileMinDepthImageUnit, minDepth_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

void PenumbraBand::findRuns(float penumbra, const glm::mat4& projection) {
  if (!runsProgram_) runsProgram_ = Program::compute("techniques/distance_transform/edtsm_penumbra_band.comp");
  // edtsm_penumbra_band.h; the margins cover the rounding of the distance eq. 8 compares
  // with P/2 and of the bound itself.
  const float p00 = projection[0][0], p11 = projection[1][1];
  const float pixelsPerTan = std::max(0.5f * float(size_.x) * p00, 0.5f * float(size_.y) * p11);
  const float stretch = std::sqrt(1.0f + 1.0f / (p00 * p00) + 1.0f / (p11 * p11));
  const float halfPenumbra = 0.5f * penumbra * 1.001f;
  // The bound holds for glm::perspective's form (scene/view.cpp); any other: the whole column.
  const bool perspective = projection[2][3] == -1.0f && projection[3][3] == 0.0f && projection[1][0] == 0.0f &&
                           projection[0][1] == 0.0f && projection[2][0] == 0.0f && projection[2][1] == 0.0f;
  const float scale = perspective ? 1.01f * pixelsPerTan * stretch * halfPenumbra : std::numeric_limits<float>::infinity();
  runsProgram_.use();
  runsProgram_.set("uSize", size_);
  runsProgram_.set("uHalfPenumbra", penumbra > 0.0f ? halfPenumbra : 0.0f);
  runsProgram_.set("uBandScale", scale);
  runsProgram_.set("uDepthToEye", glm::vec2(projection[3][2], projection[2][2]));
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPenumbraRunsBufferBinding, runs_.id());
  glDispatchCompute(GLuint((tiles_.x + 63) / 64), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void PenumbraBand::end() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPenumbraRunsBufferBinding, 0);
  glBindImageTexture(kTileSeedsImageUnit, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindImageTexture(kTileMinDepthImageUnit, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
}

}  // namespace testbed::distance_transform
