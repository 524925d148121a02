// What EDTSM's screen passes share (EDTSM* §3.3–3.4): the receiver's depth as the
// camera's depth buffer would hold it, which decides whether two pixels lie on the same
// surface ("edge awareness"; the paper's threshold is 2.5e-3 of that depth).
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
//
// The rbsm pass stores it beside the hard visibility as (v, depth), with depth −1 where
// the later passes must not look: off the receivers, and on receivers facing away from
// the light. Those are shadowed by the facing rule, not by an occluder, so they make no
// seeds, take no penumbra and stay out of the mean filter, and the terminator is not
// softened (EDTSM* keeps penumbrae apart from self-shadowing).
#include "testbed/glsl/receiver.glsl"

uniform mat4 uCameraViewProjection;
uniform float uDepthThreshold;

float cameraDepth(vec3 position) {
  vec4 clip = uCameraViewProjection * vec4(position, 1.0);
  return clip.z / clip.w * 0.5 + 0.5;
}

bool sameSurface(float depthA, float depthB) { return abs(depthA - depthB) <= uDepthThreshold; }

// (value, depth) at `pixel` of an RG texture in the layout above; depth −1 off the screen.
vec2 fetchWithDepth(sampler2D map, ivec2 pixel) {
  ivec2 size = textureSize(map, 0);
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, size))) return vec2(0.0, -1.0);
  return texelFetch(map, pixel, 0).xy;
}
