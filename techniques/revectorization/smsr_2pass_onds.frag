#version 450 core
// smsr-2pass's ONDS debug view: what its screen-space search measured, coloured as the
// family's debug.frag colours the light-space ONDS (x red, y green as d_on = 1 − α; blue
// marks a U-shape; black off the edges).
#include "techniques/revectorization/smsr_2pass_search.glsl"

layout(location = 0) out vec4 outColor;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  Receiver r;
  if (!loadReceiver(pixel, r)) discard;
  outColor = vec4(0.0, 0.0, 0.0, 1.0);
  if (facesAwayFromLight(r)) return;
  RvSample s = twoPassSample(pixel, r);
  if (!s.edge) return;
  outColor.r = s.x.kind == RV_NO_END ? 0.0 : 1.0 - s.x.alpha;
  outColor.g = s.y.kind == RV_NO_END ? 0.0 : 1.0 - s.y.alpha;
  outColor.b = (s.x.kind == RV_U || s.y.kind == RV_U) ? 1.0 : 0.0;
}
