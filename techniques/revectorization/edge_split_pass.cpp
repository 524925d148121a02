#include "techniques/revectorization/edge_split_pass.h"

namespace testbed::revectorization {

void EdgeSplitPass::setDefines(const std::string& defines) {
  if (defines == defines_) return;
  defines_ = defines;
  classify_ = Program();
  edges_ = Program();
}

void EdgeSplitPass::prepare(const VisibilityTarget& out) {
  if (!classify_) {
    classify_ = Program::graphics("testbed/render/fullscreen.vert", fragmentKey_, defines_ + "#define RV_CLASSIFY 1\n");
    edges_ = Program::graphics("testbed/render/fullscreen.vert", fragmentKey_, defines_);
    empty_ = VertexArray::create();
  }
  const Texture& visibility = out.texture;
  if (marks_ && marks_.width() == visibility.width() && marks_.height() == visibility.height() &&
      targetTexture_ == visibility.id())
    return;
  marks_ = Texture::create2D(GL_DEPTH_COMPONENT16, visibility.width(), visibility.height());
  target_ = Framebuffer::create();
  target_.attachColor(0, visibility);
  target_.attachDepth(marks_);
  target_.finish({0});
  targetTexture_ = visibility.id();
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
  prepare(out);
  glBindFramebuffer(GL_FRAMEBUFFER, target_.id());
  glEnable(GL_DEPTH_TEST);
  {
    auto scope = timer.scope(classifyPass);
    const float farthest = 1.0f;
    glClearNamedFramebufferfv(target_.id(), GL_DEPTH, 0, &farthest);
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

}  // namespace testbed::revectorization
