#include "testbed/render/edge_split_pass.h"

namespace testbed {

PassDeclaration EdgeSplitPass::classifyingDraw(std::string classifyPass) {
  return {.name = std::move(classifyPass),
          .paperStep = "device: answers the pixels without an edge texel and marks the rest",
          .only = TechniquePath::Fast};
}

ResourceDeclaration EdgeSplitPass::declaredMarks() {
  return {.name = "edge-marks", .formats = {GL_DEPTH_COMPONENT16}, .size = SizeRule::Screen, .role = ResourceRole::Device};
}

void EdgeSplitPass::setDefines(const std::string& defines) {
  if (defines == defines_) return;
  defines_ = defines;
  classify_ = Program();
  edges_ = Program();
  full_ = Program();
}

void EdgeSplitPass::prepare(const VisibilityTarget& out, TechniquePath path) {
  if (!empty_) empty_ = VertexArray::create();
  if (path == TechniquePath::Paper) {
    if (!full_) full_ = Program::graphics("testbed/render/fullscreen.vert", fragmentKey_, defines_);
    return;
  }
  if (!classify_) {
    classify_ = Program::graphics("testbed/render/fullscreen.vert", fragmentKey_,
                                  defines_ + "#define SCREEN_PASS_CLASSIFY 1\n");
    edges_ = Program::graphics("testbed/render/fullscreen.vert", fragmentKey_, defines_ + "#define SCREEN_PASS_MARKED 1\n");
  }
  // Depth 0 marks an edge pixel, 1 one the classifying draw answered.
  const glm::ivec2 size(out.texture.width(), out.texture.height());
  auto label = allocating(declaredMarks());
  target_.ensure({.size = size, .depth = GL_DEPTH_COMPONENT16, .borrowedColor = &out.texture});
}

void EdgeSplitPass::drawScreen(const Program& program, glm::ivec2 size) const {
  glViewport(0, 0, size.x, size.y);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  program.use();
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void EdgeSplitPass::draw(const FrameInputs& in, const VisibilityTarget& out, PassTimer& timer,
                         const std::function<void(const Program&)>& bind, const std::string& classifyPass,
                         const std::string& edgePass) {
  prepare(out, in.path);
  if (in.path == TechniquePath::Paper) {
    auto scope = timer.scope(edgePass);
    glBindFramebuffer(GL_FRAMEBUFFER, out.framebuffer.id());
    glDisable(GL_DEPTH_TEST);
    bind(full_);
    drawScreen(full_, in.size);
    return;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer().id());
  glEnable(GL_DEPTH_TEST);
  {
    auto scope = timer.scope(classifyPass);
    const float farthest = 1.0f;
    glClearNamedFramebufferfv(target_.framebuffer().id(), GL_DEPTH, 0, &farthest);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_ALWAYS);
    bind(classify_);
    drawScreen(classify_, in.size);
  }
  {
    // The screen triangle lies at window depth 0.5: it passes where the mark is 0.
    auto scope = timer.scope(edgePass);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_GREATER);
    bind(edges_);
    drawScreen(edges_, in.size);
  }
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
}

}  // namespace testbed
