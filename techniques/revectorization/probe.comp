#version 450 core
// Unit-test probe (revectorization_glsl_test.cpp): evaluates the real visibility functions
// of the family for a list of light-space samples (uv, light depth), without a G-buffer.
// uFunction: 0 shadow test, 1 smsr, 2 rsmss, 3 rpcf-smsr, 4 rpcf-rsmss (uImproved and
// uKernel as the techniques set them); 5 rpcf-smsr and 6 rpcf-rsmss as their screen pass
// computes them (classified from the tile bounds of rpcf_tiles.h, else the edge taps only); 7 rvClassify and
// 8 rvClassifyFetched (uImproved as bothSides), packed as rvPackClassified; 9 row uRow of
// rpcfBlockTests and 10 rpcfRowTests of that row, as taps | rim << k; 11 rpcfRegularBlock and
// 12 rpcfRegularBlockPlain (1 regular, 0 not).
layout(local_size_x = 64) in;
#include "techniques/revectorization/rpcf_smsr.glsl"
#include "techniques/revectorization/rpcf_rsmss.glsl"

#include "testbed/glsl/units.glsl"
layout(std430, binding = kProbeInputBufferBinding) readonly buffer Samples { vec4 samples[]; };  // xy uv, z depth
layout(std430, binding = kProbeOutputBufferBinding) writeonly buffer Results { float results[]; };
uniform int uFunction;
uniform int uCount;
uniform int uRow;

// s, d and edge of a classified sample as one exact integer.
float rvPackClassified(RvSample r) {
  return r.s + dot(r.d, vec4(2.0, 4.0, 8.0, 16.0)) + (r.edge ? 32.0 : 0.0);
}

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= uCount) return;
  vec2 uv = samples[i].xy;
  float z = samples[i].z;
  float v;
  switch (uFunction) {
    case 1: v = smsrVisibility(uv, z); break;
    case 2: v = rsmssVisibility(uv, z); break;
    case 3: v = rpcfSmsrVisibility(uv, z); break;
    case 4: v = rpcfRsmssVisibility(uv, z); break;
    case 5: if (!rpcfTileClassify(uv, z, v)) v = rpcfSmsrEdgeVisibility(uv, z); break;
    case 6: if (!rpcfTileClassify(uv, z, v)) v = rpcfRsmssEdgeVisibility(uv, z); break;
    case 7: v = rvPackClassified(rvClassify(uv, z, uImproved == 1)); break;
    case 8: v = rvPackClassified(rvClassifyFetched(uv, z, uImproved == 1)); break;
    case 9: {
      uvec2 rows[kRpcfRows];
      rpcfBlockTests(ivec2(floor(uv * vec2(uShadowMapSize))), z, rows);
      v = float(rows[uRow].x | (rows[uRow].y << uint(uKernel)));
      break;
    }
    case 10: {
      uvec2 row = rpcfRowTests(ivec2(floor(uv * vec2(uShadowMapSize))), uRow - uKernel / 2 - 1, uKernel / 2, z);
      v = float(row.x | (row.y << uint(uKernel)));
      break;
    }
    case 11: v = rpcfRegularBlock(uv, ivec2(floor(uv * vec2(uShadowMapSize)))) ? 1.0 : 0.0; break;
    case 12: v = rpcfRegularBlockPlain(uv, ivec2(floor(uv * vec2(uShadowMapSize)))) ? 1.0 : 0.0; break;
    default: v = shadowTest(uv, z, uBias); break;
  }
  results[i] = v;
}
