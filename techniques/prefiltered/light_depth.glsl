// The depth the pre-filtered maps store: the light's linear view depth, normalized to
// [0, 1] between its near and far planes, for spot lights as for directional ones.
// Not the depth buffer's value: for a perspective light that is hyperbolic and crowds the
// whole scene into a sliver below 1 (the wall scene lies within [0.985, 0.995]), where the
// exponential warps and the variance floors would have nothing to work with. The papers
// all filter a linear depth.
#include "testbed/glsl/light.glsl"

float lightLinearDepth(vec3 world) {
  float distanceAlongAxis = -(uLightView * vec4(world, 1.0)).z;
  return (distanceAlongAxis - uLightNear) / (uLightFar - uLightNear);
}
