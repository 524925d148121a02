#include "testbed/render/depth_image.h"

#include "testbed/glsl/units.h"

namespace testbed {

std::string DepthImage::defines() const {
  switch (layout_) {
    case Layout::Texture: return "#define RV_DEPTH_TEXTURE 1\n";
    case Layout::Texels: return "#define RV_DEPTH_TEXELS 1\n";
    case Layout::Blocks: break;
  }
  return "#define RV_DEPTH_BLOCKS 1\n";
}

ResourceDeclaration DepthImage::declared(Layout layout) {
  const bool texels = layout == Layout::Texels;
  return {.name = "depth-image",
          .formats = {GLenum(texels ? GL_R32F : GL_RGBA32F)},
          .size = texels ? SizeRule::ShadowMap : SizeRule::HalfShadowMap,
          .role = ResourceRole::Device};
}

PassDeclaration DepthImage::declaredPass() {
  return {.name = "depth-copy",
          .paperStep = "device: copies the shadow map's depths into the image the walks load one at a time",
          .only = TechniquePath::Fast};
}

void DepthImage::update(const Texture& shadowMap, PassTimer& timer) {
  if (layout_ == Layout::Texture) {
    image_ = RenderTarget();
    return;
  }
  if (!copy_ || copyLayout_ != layout_) {
    copy_ = Program::graphics("testbed/render/fullscreen.vert", "testbed/render/depth_image.frag", defines());
    copyLayout_ = layout_;
  }
  const bool texels = layout_ == Layout::Texels;
  const glm::ivec2 size = texels ? glm::ivec2(shadowMap.width(), shadowMap.height())
                                 : glm::ivec2((shadowMap.width() + 1) / 2, (shadowMap.height() + 1) / 2);
  {
    auto label = allocating(declared(layout_));
    image_.ensure({.size = size, .color = GLenum(texels ? GL_R32F : GL_RGBA32F)});
  }
  auto scope = timer.scope(declaredPass().name);
  glBindTextureUnit(kShadowMapTextureUnit, shadowMap.id());
  copy_.use();
  copy_.set("uShadowMap", kShadowMapTextureUnit);
  // Image loads see a draw's framebuffer writes without a barrier (those order shader
  // stores only).
  screen_.draw(copy_, image_.framebuffer(), size);
  bind();
}

void DepthImage::bind() const {
  if (layout_ == Layout::Texture) return;
  glBindImageTexture(kDepthImageUnit, image_.color().id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     layout_ == Layout::Texels ? GL_R32F : GL_RGBA32F);
}

}  // namespace testbed
