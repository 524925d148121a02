#version 450 core
// depth_image.h's copy. Blocks: the shadow map's 2×2 texel blocks as textureGather returns
// them (the same floats as texelFetch), one per texel of the RGBA32F target: (0,0), (1,0),
// (0,1), (1,1) of the block in x, y, z, w; a quarter of the fragments, and a gather costs
// about two and a half fetches. Texels (RV_DEPTH_TEXELS): each texel into the R32F target.
// A draw either way: llvmpipe writes a fragment's output for fewer instructions than it
// stores to an image.
uniform sampler2D uShadowMap;
layout(location = 0) out vec4 outDepth;

void main() {
#ifdef RV_DEPTH_TEXELS
  outDepth = vec4(texelFetch(uShadowMap, ivec2(gl_FragCoord.xy), 0).r);
#else
  // The block's centre: 0.5 texel from every texel boundary, so the gather's footprint is
  // the block whatever the rounding.
  const vec2 centre = (2.0 * floor(gl_FragCoord.xy) + 1.0) / vec2(textureSize(uShadowMap, 0));
  outDepth = textureGather(uShadowMap, centre).wzxy;  // gathered as (0,1), (1,1), (1,0), (0,0)
#endif
}
