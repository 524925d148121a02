#version 450 core
// depth_image.h: the shadow map's 2×2 texel blocks, as textureGather returns them (the
// same floats as texelFetch), one per texel of the RGBA32F target: (0,0), (1,0), (0,1),
// (1,1) of the block in x, y, z, w. A draw, and a quarter of the fragments: llvmpipe
// writes a fragment's output for fewer instructions than it stores to an image, and a
// gather costs about two and a half fetches.
uniform sampler2D uShadowMap;
layout(location = 0) out vec4 outBlock;

void main() {
  // The block's centre: 0.5 texel from every texel boundary, so the gather's footprint is
  // the block whatever the rounding.
  const vec2 centre = (2.0 * floor(gl_FragCoord.xy) + 1.0) / vec2(textureSize(uShadowMap, 0));
  const vec4 g = textureGather(uShadowMap, centre);  // (0,1), (1,1), (1,0), (0,0)
  outBlock = g.wzxy;
}
