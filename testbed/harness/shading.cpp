#include "testbed/harness/shading.h"

#include <algorithm>

#include <glm/glm.hpp>

#include "testbed/glsl/units.h"

namespace testbed {

ImageF shadeVisibility(const ImageF& positions, const ImageF& normals, const LightTransforms& light,
                       const ImageF& visibility) {
  constexpr float kAmbient = 0.15f, kAlbedo = 0.85f;
  const glm::vec3 background(0.18f, 0.2f, 0.24f);
  ImageF image;
  image.width = visibility.width;
  image.height = visibility.height;
  image.channels = 3;
  image.pixels.resize(std::size_t(image.width) * image.height * 3);
  for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i) {
    glm::vec3 color = background;
    if (positions.pixels[i * 4 + 3] >= 0.5f) {
      const glm::vec3 p(positions.pixels[i * 4], positions.pixels[i * 4 + 1], positions.pixels[i * 4 + 2]);
      const glm::vec3 n(normals.pixels[i * 3], normals.pixels[i * 3 + 1], normals.pixels[i * 3 + 2]);
      const glm::vec3 l = light.orthographic ? -light.direction : glm::normalize(light.position - p);
      const float v = std::clamp(visibility.pixels[i], 0.0f, 1.0f);
      color = glm::vec3(kAlbedo * (kAmbient + (1.0f - kAmbient) * std::max(glm::dot(n, l), 0.0f) * v));
    }
    for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = color[c];
  }
  return image;
}

ShadingPass::ShadingPass(glm::ivec2 size) : size_(size) { target_.ensure({.size = size, .color = GL_RGBA8}); }

void ShadingPass::draw(const GBuffer& gbuffer, const LightTransforms& light, const Texture& visibility) {
  if (!program_) program_ = Program::graphics("testbed/render/fullscreen.vert", "testbed/harness/shading.frag");
  glBindTextureUnit(kGPositionTextureUnit, gbuffer.position().id());
  glBindTextureUnit(kShadingNormalTextureUnit, gbuffer.shadingNormal().id());
  glBindTextureUnit(kShadingVisibilityTextureUnit, visibility.id());
  program_.use();
  program_.set("uPosition", kGPositionTextureUnit);
  program_.set("uShadingNormal", kShadingNormalTextureUnit);
  program_.set("uVisibility", kShadingVisibilityTextureUnit);
  program_.set("uOrthographic", light.orthographic ? 1 : 0);
  program_.set("uLightPosition", light.position);
  program_.set("uLightDirection", light.direction);
  screen_.draw(program_, target_.framebuffer(), size_);
}

}  // namespace testbed
