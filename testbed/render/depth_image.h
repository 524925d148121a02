#pragma once
// Where revectorization.glsl's single-texel reads (the walks of computeRD above all) find
// the shadow map's stored depths. The paper path (docs/paths.md) reads the depth texture
// itself with texelFetch, as the papers do. The fast path copies it into an image first:
// on llvmpipe an imageLoad costs far fewer instructions than a texelFetch of a depth
// texture (the edge pass of rpcf-smsr on fence: 195 → 122 M). Why exact: texelFetch and
// textureGather of the depth texture return the very floats the copy stores, so every
// test reads the same value in every layout. The classification's own gathers keep
// reading the depth texture. The copy is a pass of its own, declaredPass(), so that no
// paper step's time includes it. The layouts:
// - Texture: no copy, texelFetch of the depth texture (the paper path);
// - Blocks: RGBA32F at half the map's size, a texel per 2×2 block, drawn with one gather
//   a block (3.6 M instructions at 512²), a read picking its component;
// - Texels: R32F at the map's size, a fragment per texel (10 M at 512²), a read one load.
//   RPCF's k×k walks read so much that the cheaper reads pay for the dearer copy.
#include <string>

#include "testbed/gl/objects.h"
#include "testbed/gl/pass_timer.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"
#include "testbed/technique/declaration.h"

namespace testbed {

class DepthImage {
 public:
  enum class Layout { Texture, Blocks, Texels };

  // The copy as a technique whose fast path lays it out as `layout` (not Texture) declares it.
  static ResourceDeclaration declared(Layout layout);
  // The copy's pass, on the fast path only.
  static PassDeclaration declaredPass();

  // Copies `shadowMap` (a depth or float texture) into the image, resized to match (booked
  // as the device "depth-image"), timed as declaredPass(), and binds it; for Texture,
  // releases any copy instead.
  void update(const Texture& shadowMap, PassTimer& timer);
  // Binds the image at kDepthImageUnit (testbed/glsl/units.glsl) for reading (nothing for
  // Texture).
  void bind() const;
  // The layout (Blocks unless set), and the defines revectorization.glsl (and
  // depth_image.frag) read it from.
  void setLayout(Layout layout) { layout_ = layout; }
  Layout layout() const { return layout_; }
  std::string defines() const;

 private:
  Layout layout_ = Layout::Blocks;
  Program copy_;
  Layout copyLayout_ = Layout::Texture;  // copy_'s
  RenderTarget image_;  // drawn into, read as an image
  ScreenPass screen_;
};

}  // namespace testbed
