// RPCF + RSMSS (GI 2016 §3.4, eq. 3): PCF over a k×k block of texels whose every sample
// is s where (d_c)_rg = 0 and the RSMSS visibility otherwise (rsmssVisibility returns s
// before traversing when there is no discontinuity). Kernel 1 is RSMSS exactly.
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include "techniques/revectorization/rsmss.glsl"
#include "techniques/revectorization/rpcf.glsl"

bool rpcfRsmssClassify(vec2 uv, float depth, out float v) { return rpcfClassify(uv, depth, true, v); }

float rpcfRsmssVisibility(vec2 uv, float depth) {
  int h = uKernel / 2;
  vec2 texel = 1.0 / vec2(uShadowMapSize);
  float sum = 0.0;
  for (int y = -h; y <= h; ++y)
    for (int x = -h; x <= h; ++x) sum += rsmssVisibility(uv + vec2(x, y) * texel, depth);
  return sum / float(uKernel * uKernel);
}

// The same number as rpcfRsmssVisibility, computing only the edge taps (rpcfNextEdgeTap).
float rpcfRsmssEdgeVisibility(vec2 uv, float depth) {
  RpcfTaps taps = rpcfBeginTaps(uv, depth, true);
  while (rpcfNextEdgeTap(taps)) taps.sum += rsmssVisibility(taps.tapUv, depth);
  return rpcfEndTaps(taps);
}
