#include "techniques/revectorization/depth_image.h"

namespace testbed::revectorization {

void DepthImage::update(const Texture& shadowMap) {
  if (!copy_) copy_ = Program::compute("techniques/revectorization/depth_image.comp");
  if (image_.width() != shadowMap.width() || image_.height() != shadowMap.height())
    image_ = Texture::create2D(GL_R32F, shadowMap.width(), shadowMap.height());
  copy_.use();
  glBindTextureUnit(0, shadowMap.id());
  copy_.set("uShadowMap", 0);
  glBindImageTexture(kUnit, image_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  constexpr int kGroup = 8;  // depth_image.comp's local size
  glDispatchCompute(GLuint((shadowMap.width() + kGroup - 1) / kGroup), GLuint((shadowMap.height() + kGroup - 1) / kGroup), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  bind();
}

void DepthImage::bind() const { glBindImageTexture(kUnit, image_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F); }

}  // namespace testbed::revectorization
