#pragma once
// RPCF's classifying bound (rpcf.glsl, rpcfTileClassify): per tile of one shadow-map
// column and two rows, the least stored depth over the columns of a block centred there
// and its rim (k + 2), and the greatest over the same columns or, where shadowed texels are
// never edges (rpcf-smsr's conservative SMSR), over the taps' k columns only. A pixel reads
// the (k + 3)/2 tiles down its block's column, so it learns whether every texel of its
// block and rim tests lit, or every tap shadowed (every texel, with both sides), exactly in
// x and with at most one row to spare. Then no tap is an edge and the visibility is 0 or
// 1, the number the plain loop gives; other pixels go to the edge draw, which computes them
// in full. The bound only chooses which draw computes a pixel, never its value.
#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"

namespace testbed::revectorization {

class RpcfTiles {
 public:
  // The tiles of `shadowMap` for kernel width `kernel`, timed as "tile-bounds"; `bothSides`:
  // whether shadowed texels can be edges (the greatest spans the rim too).
  void render(const Texture& shadowMap, int kernel, bool bothSides, PassTimer& timer);
  // Binds them as uRpcfTiles to a program of the screen pass.
  void bind(const Program& program) const;

 private:
  int kernel_ = 0;
  bool bothSides_ = false;
  Program program_;
  RenderTarget target_;  // RG32F: the stored depths themselves, exactly
  ScreenPass screen_;
};

}  // namespace testbed::revectorization
