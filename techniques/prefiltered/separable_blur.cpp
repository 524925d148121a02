#include "techniques/prefiltered/separable_blur.h"

#include <string>

#include "testbed/glsl/units.h"

namespace testbed {

int SeparableBlur::pack(GLenum format) const {
  if (!packed_) return 1;
  return format == GL_R32F ? 4 : format == GL_RG32F ? 2 : 1;
}

int SeparableBlur::layers(GLenum format) const {
  return packed_ && (format == GL_RGBA32F || format == GL_RGBA16) ? kLayers : 1;
}

void SeparableBlur::ensure(glm::ivec2 size, GLenum format, bool blurred) {
  if (!blurred) {
    scratch_ = RenderTarget();
    return;
  }
  const int p = pack(format), l = layers(format);
  GpuMemoryLedger::Label label("blur-scratch", ResourceRole::Paper);
  // Packed or layered: the same bytes as the plain texture where the width is a multiple
  // of the pack.
  scratch_.ensure({.size = {(size.x + p * l - 1) / (p * l), size.y},
                   .color = p > 1 ? GLenum(GL_RGBA32F) : format,
                   .colorLayers = l > 1 ? l : 0});
}

TexelRect SeparableBlur::reads(const TexelRect& region, GLenum format, int radius, int size) const {
  if (region.empty()) return region;
  const int group = pack(format) * layers(format);
  const TexelRect rows{{region.min.x / group * group, region.min.y}, {region.max.x / group * group + group - 1, region.max.y}};
  return rows.grown(glm::ivec2(radius), glm::ivec2(size));
}

void SeparableBlur::run(const Texture& moments, const Framebuffer& target, const std::vector<float>& weights,
                        const TexelRect& region) {
  const int radius = static_cast<int>(weights.size()) - 1;
  const int p = pack(moments.internalFormat()), l = layers(moments.internalFormat());
  if (!rows_ || radius != radius_ || p != pack_ || l != layers_) {
    const auto program = [&](const char* step, bool columns) {
      return Program::graphics("testbed/render/fullscreen.vert", "techniques/prefiltered/blur.frag",
                               "#define BLUR_RADIUS " + std::to_string(radius) + "\n#define BLUR_STEP " + step +
                                   "\n#define BLUR_STEP_COLUMNS " + (columns ? "1" : "0") + "\n#define BLUR_PACK " +
                                   std::to_string(p) + "\n#define BLUR_LAYERS " + std::to_string(l) + "\n");
    };
    rows_ = program("ivec2(1, 0)", false);
    columns_ = program("ivec2(0, 1)", true);
    radius_ = radius;
    pack_ = p;
    layers_ = l;
  }
  for (const Program* program : {&rows_, &columns_}) {
    program->set("uWeights", weights);
    program->set("uSource", kBlurSourceTextureUnit);
  }
  const glm::ivec2 size(moments.width(), moments.height());
  glBindTextureUnit(kBlurSourceTextureUnit, moments.id());
  {
    // The scratch texels the column pass reads: the groups holding the region's columns,
    // `radius` rows either side.
    const int group = p * l;
    const TexelRect groups{{region.min.x / group, region.min.y}, {region.max.x / group, region.max.y}};
    ScissorTo scissor(groups.grown({0, radius}, {scratch_.color().width(), size.y}));
    screen_.draw(rows_, scratch_.framebuffer(), {scratch_.color().width(), size.y});
  }
  glBindTextureUnit(kBlurSourceTextureUnit, scratch_.color().id());
  ScissorTo scissor(region);
  screen_.draw(columns_, target, size);
}

}  // namespace testbed
