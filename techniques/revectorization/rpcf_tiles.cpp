#include "techniques/revectorization/rpcf_tiles.h"

#include <string>

#include "testbed/glsl/units.h"
#include "testbed/render/shadow_map_pass.h"

namespace testbed::revectorization {

PassDeclaration RpcfTiles::declaredPass() {
  return {.name = "tile-bounds",
          .paperStep = "device: each 2×2 tile's depth bounds, for the classifying draw",
          .only = TechniquePath::Fast};
}

ResourceDeclaration RpcfTiles::declaredBounds() {
  return {.name = "rpcf-tile-bounds", .formats = {GL_RG32F}, .size = SizeRule::HalfShadowMap, .role = ResourceRole::Device};
}

void RpcfTiles::render(const Texture& shadowMap, int kernel, PassTimer& timer) {
  if (kernel != kernel_ || !program_) {
    kernel_ = kernel;
    program_ = Program::graphics("testbed/render/fullscreen.vert", "techniques/revectorization/rpcf_tiles.frag",
                                 "#define RPCF_APRON " + std::to_string(kernel / 2) + "\n");
  }
  const glm::ivec2 size((shadowMap.width() + 1) / 2, (shadowMap.height() + 1) / 2);
  auto label = allocating(declaredBounds());
  if (target_.ensure({.size = size, .color = GL_RG32F})) target_.color().setFilter(GL_NEAREST, GL_NEAREST);
  auto scope = timer.scope(declaredPass().name);
  bindShadowMap(program_, shadowMap);
  screen_.draw(program_, target_.framebuffer(), size);
}

void RpcfTiles::bind(const Program& program) const {
  glBindTextureUnit(kRpcfTileBoundsTextureUnit, target_.color().id());
  program.set("uRpcfTiles", kRpcfTileBoundsTextureUnit);
}

}  // namespace testbed::revectorization
