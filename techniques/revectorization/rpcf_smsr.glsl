// RPCF + SMSR (GI 2016 §3.4, eq. 2): PCF over a k×k block of texels whose every sample is
// revectorized with the SMSR visibility. Eq. 2's shortcuts (0 where s = 0, 1 where d_c = 0)
// are what smsrVisibility does before any traversal. Samples move by whole texels, so
// each keeps the receiver's sub-texel position p and depth; kernel 1 is SMSR exactly.
// GI 2016: Macedo & Apolinário, "Revectorization-Based Shadow Mapping", Graphics Interface 2016.
#include "testbed/render/revectorization/smsr.glsl"
#include "techniques/revectorization/rpcf.glsl"

DEFINE_KERNEL_MEAN(rpcfSmsrVisibility, smsrVisibility)

// The same number as rpcfSmsrVisibility, computing only the edge taps (rpcfNextEdgeTap).
float rpcfSmsrEdgeVisibility(vec2 uv, float depth) {
  RpcfTaps taps = rpcfBeginTaps(uv, depth, uImproved == 1);
  while (rpcfNextEdgeTap(taps)) taps.sum += smsrOf(rvTraverse(taps.tap, depth));
  return rpcfEndTaps(taps);
}
