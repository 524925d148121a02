// RenderTarget: allocates once per size and format, books its own textures (never the
// borrowed ones) in the current ledger, and gives them back when it re-makes them.
#include "testbed/gl/render_target.h"

#include <gtest/gtest.h>

#include <vector>

#include "tests/gl_fixture.h"

namespace testbed {
namespace {

class RenderTargets : public ::testing::Test {
 protected:
  void SetUp() override { test::sharedContext(); }
};

TEST_F(RenderTargets, RemakesOnlyWhenSizeOrFormatChangesAndBooksOwnedBytes) {
  GpuMemoryLedger ledger;
  GpuMemoryLedger::Scope scope(ledger);
  RenderTarget target;
  EXPECT_FALSE(target);
  EXPECT_TRUE(target.ensure({.size = {8, 4}, .color = GL_RG32F, .depth = GL_DEPTH_COMPONENT16}));
  EXPECT_TRUE(target);
  EXPECT_EQ(ledger.bytes(), 8u * 4u * (8u + 2u));
  const GLuint color = target.color().id();
  EXPECT_FALSE(target.ensure({.size = {8, 4}, .color = GL_RG32F, .depth = GL_DEPTH_COMPONENT16}));
  EXPECT_EQ(target.color().id(), color);  // kept, not re-made
  EXPECT_TRUE(target.ensure({.size = {16, 4}, .color = GL_RG32F, .depth = GL_DEPTH_COMPONENT16}));
  EXPECT_EQ(ledger.bytes(), 16u * 4u * (8u + 2u));  // the old textures went back
  EXPECT_TRUE(target.ensure({.size = {16, 4}, .color = GL_R8}));
  EXPECT_FALSE(target.depth());
  EXPECT_EQ(ledger.bytes(), 16u * 4u);
  // A full mip chain counts every level: 4x4 + 2x2 + 1x1 texels.
  EXPECT_TRUE(target.ensure({.size = {4, 4}, .color = GL_R8, .colorLevels = 0}));
  EXPECT_EQ(target.color().levels(), 3);
  EXPECT_EQ(ledger.bytes(), 21u);
}

// colorLayers: one array texture, its layer i drawn at colour attachment i.
TEST_F(RenderTargets, LayeredColourDrawsEachLayerAtItsAttachment) {
  GpuMemoryLedger ledger;
  GpuMemoryLedger::Scope scope(ledger);
  RenderTarget target;
  EXPECT_TRUE(target.ensure({.size = {2, 2}, .color = GL_R32F, .colorLayers = 3}));
  EXPECT_EQ(ledger.bytes(), 2u * 2u * 4u * 3u);
  EXPECT_FALSE(target.ensure({.size = {2, 2}, .color = GL_R32F, .colorLayers = 3}));
  for (int layer = 0; layer < 3; ++layer) {
    const float value = float(layer + 1);
    glClearNamedFramebufferfv(target.framebuffer().id(), GL_COLOR, layer, &value);
  }
  std::vector<float> texels(2 * 2 * 3);
  glGetTextureImage(target.color().id(), 0, GL_RED, GL_FLOAT, GLsizei(texels.size() * sizeof(float)), texels.data());
  for (int layer = 0; layer < 3; ++layer)
    for (int i = 0; i < 4; ++i) EXPECT_EQ(texels[layer * 4 + i], float(layer + 1)) << "layer " << layer;
  EXPECT_TRUE(target.ensure({.size = {2, 2}, .color = GL_R32F}));  // back to a plain 2D texture
  EXPECT_EQ(ledger.bytes(), 2u * 2u * 4u);
}

TEST_F(RenderTargets, BorrowedTexturesAreAttachedNotBookedAndFollowed) {
  const Texture first = Texture::create2D(GL_R32F, 8, 8), second = Texture::create2D(GL_R32F, 8, 8);
  GpuMemoryLedger ledger;
  GpuMemoryLedger::Scope scope(ledger);
  RenderTarget target;
  EXPECT_TRUE(target.ensure({.size = {8, 8}, .depth = GL_DEPTH24_STENCIL8, .borrowedColor = &first}));
  EXPECT_EQ(ledger.bytes(), 8u * 8u * 4u);  // the stencil buffer only
  EXPECT_FALSE(target.color());
  GLint attached = 0;
  glGetNamedFramebufferAttachmentParameteriv(target.framebuffer().id(), GL_COLOR_ATTACHMENT0,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &attached);
  EXPECT_EQ(GLuint(attached), first.id());
  // A depth-stencil format is attached with its stencil.
  glGetNamedFramebufferAttachmentParameteriv(target.framebuffer().id(), GL_STENCIL_ATTACHMENT,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &attached);
  EXPECT_EQ(GLuint(attached), target.depth().id());
  const GLuint stencil = target.depth().id();
  // Another borrowed texture: a new framebuffer, the owned stencil kept.
  EXPECT_FALSE(target.ensure({.size = {8, 8}, .depth = GL_DEPTH24_STENCIL8, .borrowedColor = &second}));
  EXPECT_EQ(target.depth().id(), stencil);
  glGetNamedFramebufferAttachmentParameteriv(target.framebuffer().id(), GL_COLOR_ATTACHMENT0,
                                             GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &attached);
  EXPECT_EQ(GLuint(attached), second.id());
  EXPECT_EQ(ledger.bytes(), 8u * 8u * 4u);
}

}  // namespace
}  // namespace testbed
