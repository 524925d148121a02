#pragma once
// Puts the viewer's image on the window: quantized on the CPU exactly as PNGs are written
// (quantize8), so the window shows the bytes a screenshot holds, then blitted 1:1 (or
// scaled to fit, nearest) into the part of the window right of the panel.
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"
#include "testbed/gl/render_target.h"
#include "testbed/io/image_io.h"

namespace testbed::viewer {

struct Rect {
  glm::ivec2 origin{0};  // top-left, window pixels (y down)
  glm::ivec2 size{0};
  bool contains(glm::vec2 p) const {
    return p.x >= origin.x && p.y >= origin.y && p.x < origin.x + size.x && p.y < origin.y + size.y;
  }
};

// Where an image of `image` pixels lands in `area`: 1:1 at its top-left when it fits,
// otherwise scaled down to fit with its aspect kept.
Rect placeImage(glm::ivec2 image, const Rect& area);

class Display {
 public:
  // Replaces the shown image (one channel is shown as grey).
  void upload(const ImageF& image);
  // Clears the default framebuffer (`framebuffer` pixels) and draws the image into `where`.
  void draw(glm::ivec2 framebuffer, const Rect& where) const;

 private:
  RenderTarget source_;  // the uploaded image, RGBA8, blitted to the window
};

// The default framebuffer's back buffer as RGB, top-down (after the panel is drawn).
ImageF readWindow(glm::ivec2 framebuffer);

}  // namespace testbed::viewer
