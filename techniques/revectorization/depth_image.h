#pragma once
// The shadow map's stored depths copied, texel for texel, into an RGBA32F image of its
// 2×2 texel blocks (half its size), which revectorization.glsl's single-texel reads (the
// walks of computeRD above all) load with imageLoad. Why a copy: on llvmpipe an imageLoad
// costs far fewer instructions than a texelFetch of a depth texture (the walks' edge pass
// of rpcf-smsr on fence: 195 → 122 M), and the copy is one gather and one fragment write
// per block. Why exact: a gather of the depth texture returns the very floats texelFetch
// returns, so every test reads the value it read before. The classification's own
// gathers keep reading the depth texture. The copy belongs to the technique's cost:
// callers time it inside their first pass after the shadow map.
#include "testbed/gl/objects.h"
#include "testbed/gl/render_target.h"
#include "testbed/render/screen_pass.h"

namespace testbed::revectorization {

class DepthImage {
 public:
  // revectorization.glsl's uShadowImage; clear of the image units the family's and
  // EDTSM's shaders use otherwise.
  static constexpr GLuint kUnit = 5;

  // Copies `shadowMap` (a depth or float texture) into the image, resized to match (booked
  // in the current GpuMemoryLedger), and binds it.
  void update(const Texture& shadowMap);
  // Binds the image at kUnit for reading.
  void bind() const;

 private:
  Program copy_;
  RenderTarget image_;  // RGBA32F colour, a texel per 2×2 block: drawn into, read as an image
  ScreenPass screen_;
};

}  // namespace testbed::revectorization
