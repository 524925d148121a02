#include "testbed/render/gbuffer_pass.h"

#include "testbed/render/uniform_check.h"

namespace testbed {

GBuffer::GBuffer(glm::ivec2 size)
    : size_(size),
      position_(Texture::create2D(GL_RGBA32F, size.x, size.y)),
      normal_(Texture::create2D(GL_RGBA16F, size.x, size.y)),
      shadingNormal_(Texture::create2D(GL_RGBA16F, size.x, size.y)),
      depth_(Texture::create2D(GL_DEPTH_COMPONENT32F, size.x, size.y)),
      framebuffer_(Framebuffer::create()),
      program_(Program::graphics("testbed/render/gbuffer.vert", "testbed/render/gbuffer.frag")) {
  framebuffer_.attachColor(0, position_);
  framebuffer_.attachColor(1, normal_);
  framebuffer_.attachColor(2, shadingNormal_);
  framebuffer_.attachDepth(depth_);
  framebuffer_.finish({0, 1, 2});
}

void GBuffer::render(const GpuScene& geometry, const ViewProjection& camera) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, size_.x, size_.y);
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 1, zero);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 2, zero);
  glClearNamedFramebufferfi(framebuffer_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);  // open meshes (planes, holes) are seen from both sides
  glDisable(GL_POLYGON_OFFSET_FILL);
  program_.use();
  program_.set("uViewProjection", camera.viewProjection());
  requireUniformsSet(program_);
  geometry.draw();
}

}  // namespace testbed
