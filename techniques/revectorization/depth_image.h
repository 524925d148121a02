#pragma once
// Where revectorization.glsl's single-texel reads (the walks of computeRD above all) find
// the shadow map's stored depths. Why a copy at all: on llvmpipe an imageLoad costs far
// fewer instructions than a texelFetch of a depth texture (the edge pass of rpcf-smsr on
// fence: 195 → 122 M). Why exact: texelFetch and textureGather of the depth texture return
// the very floats the copy stores, so every test reads the value it read before, whichever
// layout is used. The classification's own gathers keep reading the depth texture. The copy
// belongs to the technique's cost: callers time it inside their first pass after the shadow
// map. The layouts, for different balances of copy against reads:
// - Texture: no copy, texelFetch of the depth texture;
// - Blocks: RGBA32F at half the map's size, a texel per 2×2 block, drawn with one gather
//   a block (3.6 M instructions at 512²), a read picking its component;
// - Texels: R32F at the map's size, a fragment per texel (10 M at 512²), a read one load.
// The copy costs per map texel, its savings come per screen pixel, so Auto picks from the
// ratio of the two (autoLayout).
#include <string>

#include "testbed/gl/objects.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"

namespace testbed::revectorization {

class DepthImage {
 public:
  enum class Layout { Auto, Texture, Blocks, Texels };

  // revectorization.glsl's uShadowImage; clear of the image units the family's and
  // EDTSM's shaders use otherwise.
  static constexpr GLuint kUnit = 5;

  // Auto's choice for a technique whose walks read `walkHeavy` (RPCF's k×k taps) or not,
  // for a map of `mapTexels` behind `screenPixels`: never Auto.
  static Layout autoLayout(bool walkHeavy, double mapTexels, double screenPixels);

  // The layout asked for (a technique's `depth_reads`) and whether the technique's walks
  // are RPCF's (what Auto weighs).
  void configure(Layout requested, bool walkHeavy) { requested_ = requested, walkHeavy_ = walkHeavy; }
  // Settles this frame's layout for the map's and the screen's sizes; call before
  // compiling with defines().
  void prepare(glm::ivec2 mapSize, glm::ivec2 screenSize);
  // Copies `shadowMap` (a depth or float texture) into the image, resized to match (booked
  // in the current GpuMemoryLedger), and binds it; nothing for Texture.
  void update(const Texture& shadowMap);
  // Binds the image at kUnit for reading (nothing for Texture).
  void bind() const;
  // The settled layout, and the defines revectorization.glsl (and depth_image.frag) read it from.
  Layout layout() const { return layout_; }
  std::string defines() const;

 private:
  Layout requested_ = Layout::Auto;
  bool walkHeavy_ = false;
  Layout layout_ = Layout::Blocks;  // settled by prepare()
  Program copy_;
  Layout copyLayout_ = Layout::Auto;  // copy_'s
  RenderTarget image_;  // drawn into, read as an image
  ScreenPass screen_;
};

}  // namespace testbed::revectorization
