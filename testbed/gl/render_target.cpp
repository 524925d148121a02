#include "testbed/gl/render_target.h"

namespace testbed {

bool RenderTarget::ensure(const TargetLayout& layout) {
  const GLuint borrowedColor = layout.borrowedColor ? layout.borrowedColor->id() : 0;
  const GLuint borrowedDepth = layout.borrowedDepth ? layout.borrowedDepth->id() : 0;
  const bool remake = !framebuffer_ || layout.size != size_ || layout.color != colorFormat_ ||
                      layout.colorLevels != colorLevels_ || layout.depth != depthFormat_;
  if (!remake && borrowedColor == borrowedColor_ && borrowedDepth == borrowedDepth_) return false;
  if (remake) {
    color_ = layout.color ? Texture::create2D(layout.color, layout.size.x, layout.size.y, layout.colorLevels) : Texture();
    depth_ = layout.depth ? Texture::create2D(layout.depth, layout.size.x, layout.size.y) : Texture();
    size_ = layout.size;
    colorFormat_ = layout.color;
    colorLevels_ = layout.colorLevels;
    depthFormat_ = layout.depth;
  }
  framebuffer_ = Framebuffer::create();
  const Texture* color = layout.borrowedColor ? layout.borrowedColor : (color_ ? &color_ : nullptr);
  const Texture* depth = layout.borrowedDepth ? layout.borrowedDepth : (depth_ ? &depth_ : nullptr);
  if (color) framebuffer_.attachColor(0, *color);
  if (depth) framebuffer_.attachDepth(*depth);
  if (color)
    framebuffer_.finish({0});
  else
    framebuffer_.finish({});
  borrowedColor_ = borrowedColor;
  borrowedDepth_ = borrowedDepth;
  return remake;
}

}  // namespace testbed
