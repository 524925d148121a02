#pragma once
// A full-screen triangle into a framebuffer (vertex stage: render/fullscreen.vert), the
// shape of every per-pixel pass of the techniques.
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"

namespace testbed {

// The state every per-pixel pass draws in: `target` bound over `size` pixels, no depth
// test, culling or blending, `program` in use. ScreenPass::draw and passes drawing their
// own geometry over the screen (e.g. EDTSM's filter tiles) start from it.
void beginScreenDraw(const Program& program, const Framebuffer& target, glm::ivec2 size);

class ScreenPass {
 public:
  ScreenPass();
  // Draws with `program` (already configured) into `target` over `size` pixels.
  void draw(const Program& program, const Framebuffer& target, glm::ivec2 size) const;

 private:
  VertexArray empty_;  // core profile needs a bound VAO even without attributes
};

}  // namespace testbed
