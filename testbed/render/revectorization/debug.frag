#version 450 core
// Debug views of the revectorization family (GI 2016 figures 2–3), drawn untimed into an
// RGBA8 texture: uDebugView 1 = the compressed discontinuity d_c (r, g, b as table 1),
// 2 = the ONDS, d_on = 1 − α per axis (x in red, y in green; blue marks a U-shape).
// uBothSides 0 shows entering discontinuities only, as single-pass SMSR uses them.
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include "testbed/glsl/receiver.glsl"
#include "testbed/render/revectorization/revectorization.glsl"

uniform int uDebugView;
uniform int uBothSides;
layout(location = 0) out vec4 outColor;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  outColor = vec4(0.0, 0.0, 0.0, 1.0);
  if (facesAwayFromLight(r)) return;
  vec3 light = lightSpace(r.position);
  RvSample sample_ = rvSample(light.xy, light.z, uBothSides == 1);
  if (!sample_.edge) return;
  if (uDebugView == 1) {
    outColor.rgb = rvCompress(sample_.d, sample_.s);
  } else {
    outColor.r = sample_.x.kind == RV_NO_END ? 0.0 : 1.0 - sample_.x.alpha;
    outColor.g = sample_.y.kind == RV_NO_END ? 0.0 : 1.0 - sample_.y.alpha;
    outColor.b = (sample_.x.kind == RV_U || sample_.y.kind == RV_U) ? 1.0 : 0.0;
  }
}
