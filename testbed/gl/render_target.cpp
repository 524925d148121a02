#include "testbed/gl/render_target.h"

#include <vector>

namespace testbed {

bool RenderTarget::ensure(const TargetLayout& layout) {
  const GLuint borrowedColor = layout.borrowedColor ? layout.borrowedColor->id() : 0;
  const GLuint borrowedDepth = layout.borrowedDepth ? layout.borrowedDepth->id() : 0;
  const bool remake = !framebuffer_ || layout.size != size_ || layout.color != colorFormat_ ||
                      layout.colorLevels != colorLevels_ || layout.colorLayers != colorLayers_ ||
                      layout.depth != depthFormat_;
  if (!remake && borrowedColor == borrowedColor_ && borrowedDepth == borrowedDepth_) return false;
  if (remake) {
    if (!layout.color)
      color_ = Texture();
    else if (layout.colorLayers > 0)
      color_ = Texture::create2DArray(layout.color, layout.size.x, layout.size.y, layout.colorLayers);
    else
      color_ = Texture::create2D(layout.color, layout.size.x, layout.size.y, layout.colorLevels);
    depth_ = layout.depth ? Texture::create2D(layout.depth, layout.size.x, layout.size.y) : Texture();
    size_ = layout.size;
    colorFormat_ = layout.color;
    colorLevels_ = layout.colorLevels;
    colorLayers_ = layout.colorLayers;
    depthFormat_ = layout.depth;
  }
  framebuffer_ = Framebuffer::create();
  const Texture* color = layout.borrowedColor ? layout.borrowedColor : (color_ ? &color_ : nullptr);
  const Texture* depth = layout.borrowedDepth ? layout.borrowedDepth : (depth_ ? &depth_ : nullptr);
  std::vector<int> attachments;
  if (color && !layout.borrowedColor && colorLayers_ > 0) {
    for (int layer = 0; layer < colorLayers_; ++layer) {
      framebuffer_.attachColorLayer(layer, *color, layer);
      attachments.push_back(layer);
    }
  } else if (color) {
    framebuffer_.attachColor(0, *color);
    attachments.push_back(0);
  }
  if (depth) framebuffer_.attachDepth(*depth);
  framebuffer_.finish(attachments);
  borrowedColor_ = borrowedColor;
  borrowedDepth_ = borrowedDepth;
  return remake;
}

}  // namespace testbed
