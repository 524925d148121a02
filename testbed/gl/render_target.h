#pragma once
// The one place a pass allocates what it draws into: a framebuffer and its textures,
// remade when the size or a format changes. Owned textures are booked in the
// GpuMemoryLedger current when ensure() makes them, like any Texture; borrowed ones (a
// technique's visibility target, the G-buffer's depth) are attached, never booked.
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"

namespace testbed {

struct TargetLayout {
  glm::ivec2 size{0};
  GLenum color = 0;   // owned colour texture at attachment 0 (0: none)
  int colorLevels = 1;  // its mip levels (0: the full chain)
  int colorLayers = 0;  // > 0: a 2D array of that many layers instead, layer i at attachment i
  GLenum depth = 0;   // owned depth or depth-stencil texture (0: none)
  const Texture* borrowedColor = nullptr;  // attached at 0 instead of an owned colour
  const Texture* borrowedDepth = nullptr;  // attached instead of an owned depth
};

class RenderTarget {
 public:
  // Makes the target match `layout`: the owned textures are re-made when the size or a
  // format differs from the last call (true is returned, so the caller sets their
  // filtering), the framebuffer also when a borrowed texture is another.
  bool ensure(const TargetLayout& layout);

  const Framebuffer& framebuffer() const { return framebuffer_; }
  const Texture& color() const { return color_; }
  const Texture& depth() const { return depth_; }
  explicit operator bool() const { return bool(framebuffer_); }

 private:
  glm::ivec2 size_{0};
  GLenum colorFormat_ = 0, depthFormat_ = 0;
  int colorLevels_ = 1, colorLayers_ = 0;
  GLuint borrowedColor_ = 0, borrowedDepth_ = 0;
  Texture color_, depth_;
  Framebuffer framebuffer_;
};

}  // namespace testbed
