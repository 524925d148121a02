#include "testbed/render/screen_pass.h"

#include "testbed/render/uniform_check.h"

namespace testbed {

ScreenPass::ScreenPass() : empty_(VertexArray::create()) {}

void beginScreenDraw(const Program& program, const Framebuffer& target, glm::ivec2 size) {
  glBindFramebuffer(GL_FRAMEBUFFER, target.id());
  glViewport(0, 0, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  program.use();
}

void ScreenPass::draw(const Program& program, const Framebuffer& target, glm::ivec2 size) const {
  beginScreenDraw(program, target, size);
  requireUniformsSet(program);
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace testbed
