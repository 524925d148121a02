// RPCF + RSMSS (GI 2016 §3.4, eq. 3): PCF over a k×k block of texels whose every sample
// is s where (d_c)_rg = 0 and the RSMSS visibility otherwise (rsmssVisibility returns s
// before traversing when there is no discontinuity). Kernel 1 is RSMSS exactly.
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include "techniques/revectorization/rsmss.glsl"
#include "techniques/revectorization/rpcf.glsl"

DEFINE_KERNEL_MEAN(rpcfRsmssVisibility, rsmssVisibility)

// The same number as rpcfRsmssVisibility, computing only the edge taps (rpcfNextEdgeTap).
float rpcfRsmssEdgeVisibility(vec2 uv, float depth) {
  RpcfTaps taps = rpcfBeginTaps(uv, depth, true);
  while (rpcfNextEdgeTap(taps)) taps.sum += rsmssOf(rvTraverse(taps.tap, depth));
  return rpcfEndTaps(taps);
}
