#version 450 core
// smsr-2pass, pass 1 (Bondarev 2014, "First pass"): the compressed discontinuity of every
// receiver into a screen-space RGBA8 map: rg = d_c of lit texels (entering only), b = 1 − s,
// a = 1 on receivers. Drawn over the scene's geometry from the camera (gbuffer.vert), so
// the receiver's position is this rasterization's; its normal is the G-buffer's, the very
// one every technique's facing rule reads.
// Bondarev, "Shadow Map Silhouette Revectorization", poster, I3D 2014.
#include "testbed/glsl/receiver.glsl"
#include "testbed/render/revectorization/revectorization.glsl"

layout(location = 0) in vec3 vPosition;
layout(location = 0) out vec4 outDisc;

void main() {
  Receiver r;
  r.position = vPosition;
  r.normal = texelFetch(uGNormal, ivec2(gl_FragCoord.xy), 0).xyz;
  if (facesAwayFromLight(r)) {  // shadowed, no part of the discontinuity computation
    outDisc = vec4(0.0, 0.0, 1.0, 1.0);
    return;
  }
  vec3 light = lightSpace(r.position);
  RvSample s = rvClassify(light.xy, light.z, false);  // d_c only: no traversal
  outDisc = vec4(s.s == 1.0 ? rvCompress(s.d, s.s).rg : vec2(0.0), 1.0 - s.s, 1.0);
}
