#pragma once
// A full-screen triangle into a framebuffer (vertex stage: render/fullscreen.vert), the
// shape of every per-pixel pass of the techniques.
#include <glm/glm.hpp>

#include "testbed/gl/objects.h"

namespace testbed {

class ScreenPass {
 public:
  ScreenPass();
  // Draws with `program` (already configured) into `target` over `size` pixels.
  void draw(const Program& program, const Framebuffer& target, glm::ivec2 size) const;

 private:
  VertexArray empty_;  // core profile needs a bound VAO even without attributes
};

}  // namespace testbed
