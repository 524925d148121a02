#version 450 core
// Percentage-closer soft shadows (Fernando, "Percentage-Closer Soft Shadows", SIGGRAPH 2005
// sketch), the plugin example's screen pass: three steps per receiver.
//   1. Blocker search: the mean light depth of the shadow-map texels in front of the
//      receiver, over the region through which the receiver sees the area light.
//   2. Penumbra estimate from similar triangles: w = (d_receiver − d_blocker)·w_light / d_blocker.
//   3. Percentage-closer filtering over a region of that width.
// Everything about the light comes from testbed/glsl/light.glsl; only uLightSizeUv, a
// per-frame constant, is computed on the CPU (pcss.cpp). Each tap compares against the
// receiver's plane at that tap (receiverPlaneDepth), so wide kernels do not shadow the
// receiver with itself.
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"
#include "tests/plugin_example/pcss_taps.glsl"

uniform float uBias;
uniform int uBlockerTaps;      // the search grid's taps a side
uniform int uFilterTaps;       // the filter grid's taps a side
uniform float uMinFilterTexels;  // the filter's least radius, in texels
// The area light's radius in shadow-map uv: spot, on the near plane (R / (2·near·tan(fov/2)));
// directional, per unit of light depth (tan(angular radius) / (2·extent)).
uniform float uLightSizeUv;

// A search wider than this is too sparse to find blockers; the near plane is then far in
// front of them (an unfitted depth range).
const float kMaxSearchUv = 0.25;

// The radius (uv) of the region of the map, on the near plane, through which a receiver at
// view depth zReceiver sees the light: blockers can only be there (Fernando 2005, Fig. 2).
float searchRadiusUv(float zReceiver) {
  if (uLightOrthographic == 1) return uLightSizeUv * (zReceiver - uLightNear);
  return uLightSizeUv * (zReceiver - uLightNear) / zReceiver;
}

// The penumbra's half width in uv at the receiver: Fernando's w = (d_r − d_b)·w_light / d_b
// with w_light = 2·radius, taken to the receiver's depth by the projection (÷ d_r·2·tan(fov/2)).
// A directional light's rays are parallel: w = (d_r − d_b)·2·tan(angular radius).
float penumbraRadiusUv(float zReceiver, float zBlocker) {
  if (uLightOrthographic == 1) return uLightSizeUv * (zReceiver - zBlocker);
  return uLightSizeUv * uLightNear * (zReceiver - zBlocker) / (zBlocker * zReceiver);
}

// Step 1: false when no texel in the region is in front of the receiver (fully lit).
bool averageBlockerDepth(vec3 light, vec2 gradient, float radius, out float zBlocker) {
  float sum = 0.0;
  int count = 0;
  for (int y = 0; y < uBlockerTaps; ++y)
    for (int x = 0; x < uBlockerTaps; ++x) {
      vec2 offset = gridTapOffset(x, y, uBlockerTaps, radius);
      float stored = texture(uShadowMap, light.xy + offset).r;
      if (stored < receiverPlaneDepth(light, gradient, offset) - uBias) {
        sum += linearizeLightDepth(stored);
        ++count;
      }
    }
  zBlocker = count > 0 ? sum / float(count) : 0.0;
  return count > 0;
}

// Step 3: the fraction of the filter's taps that see past the blockers.
float filteredVisibility(vec3 light, vec2 gradient, float radius) {
  float lit = 0.0;
  for (int y = 0; y < uFilterTaps; ++y)
    for (int x = 0; x < uFilterTaps; ++x) {
      vec2 offset = gridTapOffset(x, y, uFilterTaps, radius);
      lit += shadowTest(light.xy + offset, receiverPlaneDepth(light, gradient, offset), uBias);
    }
  return lit / float(uFilterTaps * uFilterTaps);
}

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) {
  float zReceiver = linearizeLightDepth(light.z);
  vec2 gradient = receiverPlaneDepthGradient(r.position, r.normal);
  // Within a degree of edge-on the facing rule has shadowed the receiver already; nearly
  // there the plane is too steep to extrapolate.
  if (any(isinf(gradient)) || any(isnan(gradient))) gradient = vec2(0.0);
  float texel = 1.0 / float(uShadowMapSize.x);
  float zBlocker;
  float search = clamp(searchRadiusUv(zReceiver), texel, kMaxSearchUv);
  if (!averageBlockerDepth(light, gradient, search, zBlocker)) return 1.0;
  float radius = max(penumbraRadiusUv(zReceiver, zBlocker), uMinFilterTexels * texel);
  return filteredVisibility(light, gradient, radius);
}

#include "testbed/glsl/screen_pass.glsl"
