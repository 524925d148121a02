#pragma once
// Light depth ranges fitted to the scene's geometry, so that the shadow map's depth
// precision (and a polygon offset counted in depth-buffer steps) is spent where the
// geometry is, whatever near/far a scene file gives. Without it the papers' spot light
// (near 1, far 1000) at 16-bit depth puts one depth step at ~0.3 world units 150 units
// away and the offset's 20 steps at ~6 units: whole shadow strips leak.
#include "testbed/scene/scene.h"
#include "testbed/scene/view.h"

namespace testbed {

// The view depths (along the light's axis; directional: from the plane through its target)
// of the scene's triangles, clipped to the light's side planes: the geometry the shadow
// map can see. found = false when none lies inside.
struct LightDepthSpan {
  bool found = false;
  double nearest = 0, farthest = 0;
};
LightDepthSpan lightDepthSpan(const Scene& scene, const LightDesc& light, float extent);

// A directional light's extent fitted to the scene: the half size of the smallest square
// centred on the target (in the light's view axes) that holds every vertex, plus a margin.
float fittedDirectionalExtent(const Scene& scene, const LightDesc& light);

// The transforms the harness renders with. With light.fit: a spot's near/far fitted to the
// span (a relative margin of kDepthMargin each side), kept within the scene's near/far; a
// directional light's depth range fitted to the span and its extent fitted when 0. Without
// fit, or when no geometry is inside, lightTransforms(light) as given.
LightTransforms fittedLightTransforms(const Scene& scene);
inline constexpr double kDepthMargin = 0.005;

// World size, along the light's rays, of one depth-buffer step (r = 2^-16, 2^-24, and
// 2^-24 for 32f depths in [0.5, 1); `offset_units` counts 16-bit steps at every format) at
// view depth d from the light: perspective r·(f−n)·d²/(f·n), orthographic r·(f−n).
double depthStepWorld(const LightTransforms& light, int depthBits, double viewDepth);

}  // namespace testbed
