#version 450 core
// Unit-test probe of silhouette_map.glsl: mode 0 runs silhouettePoint on (a, b) pairs,
// mode 1 quadrantCorner on (c, right, up, left, down, f) sets; one case per invocation.
#include "techniques/silhouette_map/silhouette_map.glsl"
layout(local_size_x = 1) in;
#include "testbed/glsl/units.glsl"
layout(std430, binding = kProbeInputBufferBinding) readonly buffer Cases { vec4 cases[]; };  // 3 vec4 a case
layout(std430, binding = kProbeOutputBufferBinding) writeonly buffer Results { vec4 results[]; };
uniform int uMode;

void main() {
  uint i = gl_GlobalInvocationID.x;
  vec4 x = cases[3 * i], y = cases[3 * i + 1], z = cases[3 * i + 2];
  if (uMode == 0) {
    vec3 point;
    bool hit = silhouettePoint(x.xyz, y.xyz, point);
    results[i] = vec4(point, hit ? 1.0 : 0.0);
  } else {
    results[i] = vec4(float(quadrantCorner(x.xy, x.zw, y.xy, y.zw, z.xy, z.zw)));
  }
}
