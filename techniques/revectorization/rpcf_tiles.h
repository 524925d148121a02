#pragma once
// RPCF's classifying bound (rpcf.glsl, rpcfTileClassify): per 2×2 tile of the shadow map
// with an apron of k/2 texels, the least and greatest stored depth, so a pixel learns
// from four fetches (the 2×2 tiles around its block) whether every texel of its taps'
// block and rim tests alike. Then no tap is an edge and the visibility is 0 or 1, the number the plain
// loop gives; other pixels go to the edge draw, which computes them in full. The bound
// only chooses which draw computes a pixel, never its value.
#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"
#include "testbed/technique/declaration.h"

namespace testbed::revectorization {

class RpcfTiles {
 public:
  // Its pass and target, devices of the fast path (declaration.h).
  static PassDeclaration declaredPass();
  static ResourceDeclaration declaredBounds();
  // The tiles of `shadowMap` for kernel width `kernel`, timed as "tile-bounds".
  void render(const Texture& shadowMap, int kernel, PassTimer& timer);
  // Binds them as uRpcfTiles to a program of the screen pass.
  void bind(const Program& program) const;

 private:
  int kernel_ = 0;
  Program program_;
  RenderTarget target_;  // RG32F: the stored depths themselves, exactly
  ScreenPass screen_;
};

}  // namespace testbed::revectorization
