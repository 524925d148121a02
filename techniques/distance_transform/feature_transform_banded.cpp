#include "techniques/distance_transform/feature_transform_banded.h"

#include <string>
#include <utility>

#include "testbed/core/error.h"
#include "testbed/glsl/units.h"

namespace testbed {
namespace {

constexpr int kGroupSide = 8;  // local_size_x and _y

GLuint groupsOfSide(int invocations) { return GLuint((invocations + kGroupSide - 1) / kGroupSide); }
int bandsOf(int pixels, int band) { return (pixels + band - 1) / band; }

Program stepProgram(const char* key, int step) {
  return Program::compute(key, "#define STEP " + std::to_string(step) + "\n");
}

}  // namespace

BandedFeatureTransformPass::BandedFeatureTransformPass(int bandPixels) : band_(bandPixels) {
  if (bandPixels < 1 || bandPixels > kMaxExtent)
    throw GlError("banded feature transform: " + std::to_string(bandPixels) + " pixels a band, out of range (1 to " +
                  std::to_string(kMaxExtent) + ")");
}

ResourceDeclaration BandedFeatureTransformPass::declaredBands(int bandPixels) {
  return {.name = "edt-bands",
          .formats = {GL_RG32I, GL_R32I},
          .size = SizeRule::ScreenBands,
          .role = ResourceRole::Paper,
          .tile = bandPixels};
}

void BandedFeatureTransformPass::run(const Texture& seeds, glm::ivec2 size, const std::function<void(int)>& afterPhase) {
  prepare(size);
  if (size.x > seeds.width() || size.y > seeds.height())
    throw GlError("banded feature transform: the seed texture is smaller than the requested size");
  if (!bandSeeds_) {
    const char* rows = "techniques/distance_transform/feature_transform_band_rows.comp";
    const char* columns = "techniques/distance_transform/feature_transform_band_columns.comp";
    bandSeeds_ = stepProgram(rows, 1);
    carry_ = stepProgram(rows, 2);
    rowSweep_ = stepProgram(rows, 3);
    proximate_ = stepProgram(columns, 1);
    merge_ = stepProgram(columns, 2);
    starts_ = stepProgram(columns, 3);
    colour_ = stepProgram(columns, 4);
  }
  const std::pair<int, const Texture*> images[] = {
      {kEdtsmOutputImageUnit, &nearest_},     {kBandSeedsImageUnit, &bandSeedsImage_},
      {kBandCarryImageUnit, &bandCarry_},     {kBandRowNearestImageUnit, &rowNearest_},
      {kLinksImageUnit, &links_},             {kBandEndsImageUnit, &bandEnds_},
      {kBandStartImageUnit, &bandStart_}};
  for (const auto& [unit, texture] : images)
    glBindImageTexture(GLuint(unit), texture->id(), 0, GL_FALSE, 0, GL_READ_WRITE, texture->internalFormat());
  const auto done = [&](int phase) {
    if (afterPhase) afterPhase(phase);
  };
  phase1(seeds);
  done(1);
  phase2();
  done(2);
  phase3();
  done(3);
  for (const auto& image : images) glBindImageTexture(GLuint(image.first), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32I);
  checkGlError("banded feature transform");
}

void BandedFeatureTransformPass::prepare(glm::ivec2 size) {
  if (size.x <= 0 || size.y <= 0 || size.x > kMaxExtent || size.y > kMaxExtent)
    throw GlError("banded feature transform: size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                  " out of range (1 to " + std::to_string(kMaxExtent) + " a side)");
  if (size == size_) return;
  // Allocated here, not at construction, so they are booked in the ledger current while
  // the technique renders.
  rowBands_ = {bandsOf(size.x, band_), size.y};
  columnBands_ = {size.x, bandsOf(size.y, band_)};
  {
    GpuMemoryLedger::Label label("edt-scratch", ResourceRole::Paper);
    nearest_ = Texture::create2D(GL_RG32I, size.x, size.y);
    rowNearest_ = Texture::create2D(GL_R32I, size.x, size.y);
    links_ = Texture::create2D(GL_RG32I, size.x, size.y);
  }
  auto label = allocating(declaredBands(band_));
  bandSeedsImage_ = Texture::create2D(GL_RG32I, rowBands_.x, rowBands_.y);
  bandCarry_ = Texture::create2D(GL_RG32I, rowBands_.x, rowBands_.y);
  bandEnds_ = Texture::create2D(GL_RG32I, columnBands_.x, columnBands_.y);
  bandStart_ = Texture::create2D(GL_R32I, columnBands_.x, columnBands_.y);
  size_ = size;
}

void BandedFeatureTransformPass::dispatch(const Program& program, int x, int y) const {
  program.use();
  program.set("uSize", size_);
  program.set("uBand", band_);
  glDispatchCompute(groupsOfSide(x), groupsOfSide(y), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

void BandedFeatureTransformPass::phase1(const Texture& seeds) {
  // The seeds may have just been written by an image store.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  glBindTextureUnit(kEdtSeedsTextureUnit, seeds.id());
  for (const Program* p : {&bandSeeds_, &carry_, &rowSweep_}) {
    p->use();
    p->set("uSeeds", kEdtSeedsTextureUnit);
  }
  dispatch(bandSeeds_, rowBands_.x, rowBands_.y);
  // One invocation a row, 64 rows a group.
  carry_.use();
  carry_.set("uSize", size_);
  carry_.set("uBand", band_);
  glDispatchCompute(GLuint((size_.y + 63) / 64), 1, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  dispatch(rowSweep_, rowBands_.x, rowBands_.y);
}

void BandedFeatureTransformPass::phase2() {
  dispatch(proximate_, columnBands_.x, columnBands_.y);
  for (int group = 1; group < columnBands_.y; group *= 2) {
    merge_.use();
    merge_.set("uGroup", group);
    const int pairs = (columnBands_.y + 2 * group - 1) / (2 * group);
    dispatch(merge_, columnBands_.x, pairs);
  }
  const GLint none = -1;  // columns without a seed keep it
  glClearTexImage(bandStart_.id(), 0, GL_RED_INTEGER, GL_INT, &none);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  dispatch(starts_, columnBands_.x, columnBands_.y);
}

void BandedFeatureTransformPass::phase3() {
  dispatch(colour_, columnBands_.x, columnBands_.y);
  // Whatever reads the result next: a texel fetch, an image load, a copy, a blit or a
  // read-back.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT | GL_PIXEL_BUFFER_BARRIER_BIT);
}

std::vector<glm::ivec2> BandedFeatureTransformPass::readNearest() const {
  std::vector<glm::ivec2> texels(std::size_t(size_.x) * std::size_t(size_.y));
  if (texels.empty()) return texels;
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(nearest_.id(), 0, GL_RG_INTEGER, GL_INT, GLsizei(texels.size() * sizeof(glm::ivec2)),
                    texels.data());
  checkGlError("reading back the banded feature transform");
  return texels;
}

}  // namespace testbed
