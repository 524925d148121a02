#version 450 core
// Unit-test probe of silhouette_corners.glsl: per case (texel x, y, depth, bias) the
// gathered corner tests and the reference's, side by side.
#include "techniques/silhouette_map/silhouette_corners.glsl"
layout(local_size_x = 1) in;
#include "testbed/glsl/units.glsl"
layout(std430, binding = kProbeInputBufferBinding) readonly buffer Cases { vec4 cases[]; };
layout(std430, binding = kProbeOutputBufferBinding) writeonly buffer Results { vec4 results[]; };  // 2 a case

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 c = cases[i];
  ivec2 texel = ivec2(c.xy);
  results[2 * i] = cornerShadowTests(texel, c.z, c.w);
  results[2 * i + 1] = cornerShadowTestsByTexel(texel, c.z, c.w);
}
