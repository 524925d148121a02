#include "testbed/viewer/display.h"

#include <algorithm>
#include <vector>

namespace testbed::viewer {

Rect placeImage(glm::ivec2 image, const Rect& area) {
  if (image.x <= area.size.x && image.y <= area.size.y) return {area.origin, image};
  const float scale = std::min(float(area.size.x) / float(image.x), float(area.size.y) / float(image.y));
  return {area.origin, glm::max(glm::ivec2(glm::vec2(image) * scale), glm::ivec2(1))};
}

void Display::upload(const ImageF& image) {
  source_.ensure({.size = {image.width, image.height}, .color = GL_RGBA8});
  // Rows go bottom-up in GL; grey images fill all three channels.
  std::vector<unsigned char> bytes(std::size_t(image.width) * image.height * 4, 255);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      unsigned char* out = &bytes[(std::size_t(image.height - 1 - y) * image.width + x) * 4];
      for (int c = 0; c < 3; ++c) out[c] = quantize8(image.at(x, y, std::min(c, image.channels - 1)));
    }
  }
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTextureSubImage2D(source_.color().id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, bytes.data());
}

void Display::draw(glm::ivec2 framebuffer, const Rect& where) const {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, framebuffer.x, framebuffer.y);
  glDisable(GL_SCISSOR_TEST);
  const float clear[4] = {0.08f, 0.08f, 0.09f, 1.0f};
  glClearNamedFramebufferfv(0, GL_COLOR, 0, clear);
  if (!source_) return;
  // Window rows are bottom-up: the rectangle's top edge is framebuffer.y - origin.y.
  const int top = framebuffer.y - where.origin.y;
  glBlitNamedFramebuffer(source_.framebuffer().id(), 0, 0, 0, source_.color().width(), source_.color().height(), where.origin.x,
                         top - where.size.y, where.origin.x + where.size.x, top, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

ImageF readWindow(glm::ivec2 framebuffer) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<unsigned char> bytes(std::size_t(framebuffer.x) * framebuffer.y * 3);
  glReadPixels(0, 0, framebuffer.x, framebuffer.y, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
  ImageF image;
  image.width = framebuffer.x;
  image.height = framebuffer.y;
  image.channels = 3;
  image.pixels.resize(bytes.size());
  const std::size_t row = std::size_t(framebuffer.x) * 3;
  for (int y = 0; y < framebuffer.y; ++y)
    for (std::size_t i = 0; i < row; ++i)
      image.pixels[std::size_t(y) * row + i] = float(bytes[std::size_t(framebuffer.y - 1 - y) * row + i]) / 255.0f;
  return image;
}

}  // namespace testbed::viewer
