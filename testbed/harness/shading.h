#pragma once
// The shaded image for people (T.png): Lambert × visibility plus ambient, on the CPU from
// the G-buffer readback. No part of any metric.
//
// ShadingPass is the same step on the GPU, the last pass of the papers' frames (EDTSM*
// Table 4 times it): the harness times it after each technique frame, outside the
// technique's passes, as the records' shading_ms, so a sweep row can add it ("shading").
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"
#include "testbed/gl/render_target.h"
#include "testbed/io/image_io.h"
#include "testbed/render/gbuffer_pass.h"
#include "testbed/render/screen_pass.h"
#include "testbed/scene/view.h"

namespace testbed {

// `positions` (xyz world position, w coverage) and `normals` (xyz) are the G-buffer
// readback, top-down; `visibility` one channel of the same size. Returns RGB, the
// background where no receiver covers the pixel.
ImageF shadeVisibility(const ImageF& positions, const ImageF& normals, const LightTransforms& light,
                       const ImageF& visibility);

class ShadingPass {
 public:
  // Allocates the `size` RGBA8 image now, so that it is never booked to the technique whose
  // frame happens to be shaded first.
  explicit ShadingPass(glm::ivec2 size);
  // Shades `visibility` (R32F, the G-buffer's size) into the RGBA8 image, the framebuffer a
  // frame would present.
  void draw(const GBuffer& gbuffer, const LightTransforms& light, const Texture& visibility);
  // The last draw's image, bottom-up as GL stores it.
  const Texture& color() const { return target_.color(); }

 private:
  Program program_;
  ScreenPass screen_;
  RenderTarget target_;
  glm::ivec2 size_;
};

}  // namespace testbed
