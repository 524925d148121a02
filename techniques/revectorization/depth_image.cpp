#include "techniques/revectorization/depth_image.h"

namespace testbed::revectorization {

DepthImage::Layout DepthImage::autoLayout(bool walkHeavy, double mapTexels, double screenPixels) {
  // Break-even ratios of map texels to screen pixels, from llvmpipe's instruction counts
  // (scripts/pass_instructions.sh, fence at 640×360 behind 512², 1024² and 2048²): a copy
  // costs about 13 instructions a map texel (Blocks) or 38 (Texels); the walks save about
  // 35 a screen pixel with Blocks for SMSR and RSMSS, and 150–190 (Blocks) or 260 (Texels)
  // for RPCF's 3×3 taps. Measured totals agree: rpcf-smsr Blocks beats Texture by 32 M at
  // 1024² (ratio 4.6) and loses by 17 M at 2048² (ratio 18.2).
  const double ratio = mapTexels / screenPixels;
  if (walkHeavy) return ratio <= 2.8 ? Layout::Texels : ratio <= 13.5 ? Layout::Blocks : Layout::Texture;
  return ratio <= 2.9 ? Layout::Blocks : Layout::Texture;
}

void DepthImage::prepare(glm::ivec2 mapSize, glm::ivec2 screenSize) {
  layout_ = requested_ != Layout::Auto
                ? requested_
                : autoLayout(walkHeavy_, double(mapSize.x) * mapSize.y, double(screenSize.x) * screenSize.y);
}

std::string DepthImage::defines() const {
  switch (layout_) {
    case Layout::Texture: return "#define RV_DEPTH_TEXTURE 1\n";
    case Layout::Texels: return "#define RV_DEPTH_TEXELS 1\n";
    case Layout::Blocks:
    case Layout::Auto: break;
  }
  return "";
}

void DepthImage::update(const Texture& shadowMap) {
  if (layout_ == Layout::Texture) {
    image_ = RenderTarget();  // unbooked: this layout holds no copy
    return;
  }
  if (!copy_ || copyLayout_ != layout_) {
    copy_ = Program::graphics("testbed/render/fullscreen.vert", "techniques/revectorization/depth_image.frag", defines());
    copyLayout_ = layout_;
  }
  const bool texels = layout_ == Layout::Texels;
  const glm::ivec2 size = texels ? glm::ivec2(shadowMap.width(), shadowMap.height())
                                 : glm::ivec2((shadowMap.width() + 1) / 2, (shadowMap.height() + 1) / 2);
  image_.ensure({.size = size, .color = GLenum(texels ? GL_R32F : GL_RGBA32F)});
  glBindTextureUnit(0, shadowMap.id());
  copy_.use();
  copy_.set("uShadowMap", 0);
  // Image loads see a draw's framebuffer writes without a barrier (those order shader
  // stores only).
  screen_.draw(copy_, image_.framebuffer(), size);
  bind();
}

void DepthImage::bind() const {
  if (layout_ == Layout::Texture) return;
  glBindImageTexture(kUnit, image_.color().id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     layout_ == Layout::Texels ? GL_R32F : GL_RGBA32F);
}

}  // namespace testbed::revectorization
