#version 450 core
// depth_image.h: each texel of the shadow map, as texelFetch returns it, into the R32F image.
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2D uShadowMap;
layout(r32f, binding = 5) uniform writeonly image2D uShadowImage;  // DepthImage::kUnit

void main() {
  const ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(texel, textureSize(uShadowMap, 0)))) return;
  imageStore(uShadowImage, texel, vec4(texelFetch(uShadowMap, texel, 0).r));
}
