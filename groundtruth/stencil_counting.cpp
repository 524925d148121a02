#include "groundtruth/stencil_counting.h"

#include "testbed/render/receiver_inputs.h"

namespace testbed {

PassDeclaration StencilCounting::declaredPass() {
  return {.name = kPass,
          .paperStep = "stencil shadow volumes, the reference of GI 2016 §4: capped volumes counted depth-fail "
                       "in one two-sided stencil pass (Everitt & Kilgard 2002)",
          .only = TechniquePath::Paper};
}

ResourceDeclaration StencilCounting::declaredStencil() {
  // The stencil comes packed with a depth buffer, as GPUs and the classic renderers keep
  // it; its depth half is unused (the exact test replaces the depth comparison).
  return {.name = "stencil", .formats = {GL_DEPTH24_STENCIL8}, .size = SizeRule::Screen, .role = ResourceRole::Paper};
}

void StencilCounting::count(const FrameInputs& in, const VisibilityTarget& out, const VertexArray& volumes,
                            GLsizei vertexCount, const glm::vec3& camera, float tieTolerance) {
  if (!countProgram_) {
    countProgram_ = Program::graphics("groundtruth/shadow_volume.vert", "groundtruth/shadow_volume_stencil.frag");
    resolveProgram_ = Program::graphics("testbed/render/fullscreen.vert", "groundtruth/volume_stencil_visibility.frag");
    screen_ = VertexArray::create();
  }
  {
    auto label = allocating(declaredStencil());
    target_.ensure({.size = in.size, .depth = GL_DEPTH24_STENCIL8, .borrowedColor = &out.texture});
  }
  glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer().id());
  glViewport(0, 0, in.size.x, in.size.y);
  glStencilMask(0xff);
  glClearNamedFramebufferfi(target_.framebuffer().id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glDisable(GL_DEPTH_TEST);  // the shader's exact test decides which faces are behind
  glDisable(GL_CULL_FACE);   // front and back faces in the one pass
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_CLAMP);  // faces reaching infinity stay unclipped
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  // A surviving fragment is a face behind the receiver (a depth-fail); with the depth
  // test off, GL applies the depth-pass slot's operation to it. Leaving a volume behind
  // the receiver (back face) +1, entering it (front face) −1.
  glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  countProgram_.use();
  bindReceiverInputs(countProgram_, in);
  countProgram_.set("uViewProjection", in.camera.viewProjection());
  countProgram_.set("uCameraPosition", camera);
  countProgram_.set("uTieTolerance", tieTolerance);
  glBindVertexArray(volumes.id());
  if (vertexCount > 0) glDrawArrays(GL_TRIANGLES, 0, vertexCount);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_STENCIL_TEST);
}

void StencilCounting::resolve(const FrameInputs& in, const VolumeLight& light, float weight) {
  glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer().id());
  glViewport(0, 0, in.size.x, in.size.y);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xff);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_BLEND);  // area-light samples add up
  glBlendFunc(GL_ONE, GL_ONE);
  resolveProgram_.use();
  resolveProgram_.set("uWeight", weight);
  bindReceiverInputs(resolveProgram_, in, light.position);
  resolveProgram_.set("uLightDirection", light.direction);
  glBindVertexArray(screen_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);  // full-screen triangle (render/fullscreen.vert)
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
}

}  // namespace testbed
