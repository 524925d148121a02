// The bias modes of the shadow-map set-up (BiasMode in technique/shadow_setup.h,
// docs/cascades.md "Bias modes"), for the techniques that take the shared set-up (sm, pcf):
// their shader defines TESTBED_BIAS_MODES before including shadow_test.glsl, which includes
// this file, and looks its receiver up through shadowLookup(). The shared-map forms of
// shadowTest then take each tap through biasedTap(). Set by
// ShadowMapScreenBase::bindBias (render/shadow_map_screen_technique.h). With the slope bias
// (the default) neither function changes a bit: the polygon offset was applied when the map
// was rendered.
#include "testbed/glsl/receiver.glsl"

// BiasMode's values, in its order.
const int kBiasSlope = 0;
const int kBiasNormal = 1;
const int kBiasReceiverPlane = 2;

uniform int uBiasMode;
uniform float uNormalOffset;       // k: the normal offset in map texels
uniform float uReceiverPlaneBias;  // c: the receiver-plane constant in window depth

// Set by shadowLookup for the taps of the receiver-plane bias: the receiver's map
// coordinates and its plane's depth gradient in (u, v).
vec2 gBiasReceiverUv = vec2(0.0);
vec2 gBiasDepthGradient = vec2(0.0);

// The map the receiver reads: its cascade's (cascades.glsl) or the light's.
mat4 biasMapViewProjection() {
#ifdef TESTBED_CASCADES
  return cascadeViewProjection(gCascade);
#else
  return uLightViewProjection;
#endif
}

// The larger world size of that map's texel at the receiver (light.glsl texelWorldSize).
float biasTexelWorld(vec3 world) {
#ifdef TESTBED_CASCADES
  vec2 texel = cascadeTexelWorld(gCascade, uShadowMapSize, lightViewDepthOf(world));
#else
  vec2 texel = texelWorldSize(uLightProjection, uShadowMapSize, lightViewDepthOf(world));
#endif
  return max(texel.x, texel.y);
}

// Normal offset (Holbert, "Normal offset shadows", GDC 2011): the point looked up lies
// k texels × sin θ along the receiver's normal, θ the angle between normal and light. A
// planar receiver's own surface, sampled at a texel centre up to half a texel diagonal away
// (t/√2), lies at most (t/√2)·tan θ nearer the light along the ray; moving d along the
// normal moves the point d/cos θ along the ray, so d ≥ (t/√2)·sin θ clears it: k = 1
// clears a nearest lookup with room for depth quantization, which the polygon offset's
// constant term (kept in this mode) covers where θ is 0. The facing rule has already
// shadowed receivers facing away (screen_pass.glsl), so the G-buffer normal faces the light.
vec3 normalOffsetPosition(Receiver r) {
  float cosTheta = clamp(dot(r.normal, towardsLight(r.position)), 0.0, 1.0);
  float sinTheta = sqrt(1.0 - cosTheta * cosTheta);
  return r.position + r.normal * (uNormalOffset * biasTexelWorld(r.position) * sinTheta);
}

// The map coordinates (uv, depth) the technique tests for the receiver r whose own are
// `light` (lightSpace of its map): the normal-offset point's, or `light` itself, the
// receiver-plane bias's gradient kept for the taps. Unclamped: an offset point beside the
// map reads its border (shadow), as any lookup there does.
vec3 shadowLookup(Receiver r, vec3 light) {
  if (uBiasMode == kBiasNormal) return lightCoordinates(biasMapViewProjection(), normalOffsetPosition(r));
  if (uBiasMode == kBiasReceiverPlane) {
    gBiasReceiverUv = light.xy;
    gBiasDepthGradient = receiverPlaneDepthGradient(biasMapViewProjection(), r.position, r.normal);
  }
  return light;
}

// The tap at `uv` of a receiver at depth `depth`, as the bias mode compares it: uv and the
// depth to compare. Receiver-plane depth bias (Isidoro, "Shadow mapping: GPU-based tips and
// techniques", GDC 2006): the tap reads the centre of the texel holding `uv` — the point the
// map's depth was rasterized at, and a lookup that cannot round to a neighbour texel, whose
// depth the plane would be wrong for by a whole texel's slope — and compares the receiver's
// plane there, less the constant: a planar receiver meets its own stored depth up to the
// depth buffer's rounding, which the constant covers; at every tap of a kernel alike.
// Isidoro takes the plane from screen derivatives of the map coordinates; the deferred pass
// has the receiver's plane exactly (receiverPlaneDepthGradient: the same 2×2 Jacobian
// inverse over two steps in the plane), which does not mix neighbouring surfaces at
// silhouettes.
void biasedTap(inout vec2 uv, inout float depth) {
  if (uBiasMode != kBiasReceiverPlane) return;
  vec2 size = vec2(uShadowMapSize);
  uv = (floor(uv * size) + 0.5) / size;
  // Not beyond the far plane, where nothing is stored: the light's depth range is fitted
  // to the scene, so beside the farthest receiver's edge the plane runs past 1, over
  // texels that hold the cleared depth 1.
  depth = min(depth + dot(gBiasDepthGradient, uv - gBiasReceiverUv), 1.0) - uReceiverPlaneBias;
}
