#pragma once
// The shadow map's stored depths copied, texel for texel, into an R32F image, which
// revectorization.glsl's single-texel reads (the walks of computeRD above all) load with
// imageLoad. Why a copy: on llvmpipe an imageLoad costs far fewer instructions than a
// texelFetch of a depth texture (the walks' edge pass on fence: 195 → 122 M), and the
// copy is one fetch and one store per texel. Why exact: texelFetch of the depth texture
// returns the very float the copy stores and imageLoad returns, so every test reads the
// value it read before. The gathers keep reading the depth texture. The copy belongs to
// the technique's cost: callers time it inside their first pass after the shadow map.
#include "testbed/gl/objects.h"

namespace testbed::revectorization {

class DepthImage {
 public:
  // revectorization.glsl's uShadowImage; clear of the image units the family's and
  // EDTSM's shaders use otherwise.
  static constexpr GLuint kUnit = 5;

  // Copies `shadowMap` (a depth or float texture) into the image, resized to match (booked
  // in the current GpuMemoryLedger), and makes the writes visible to image loads.
  void update(const Texture& shadowMap);
  // Binds the image at kUnit for reading.
  void bind() const;

 private:
  Program copy_;
  Texture image_;  // R32F
};

}  // namespace testbed::revectorization
