// What EDTSM's screen passes share (seed 004 §3.3–3.4): the receiver's depth as the
// camera's depth buffer would hold it, which decides whether two pixels lie on the same
// surface ("edge awareness"; the paper's threshold is 2.5e-3 of that depth).
#include "testbed/glsl/receiver.glsl"

uniform mat4 uCameraViewProjection;
uniform float uDepthThreshold;

float cameraDepth(vec3 position) {
  vec4 clip = uCameraViewProjection * vec4(position, 1.0);
  return clip.z / clip.w * 0.5 + 0.5;
}

// The receiver at `pixel` and its camera depth; false off the receivers or the screen.
bool receiverDepth(ivec2 pixel, out vec3 position, out float depth) {
  ivec2 size = textureSize(uGPosition, 0);
  if (any(lessThan(pixel, ivec2(0))) || any(greaterThanEqual(pixel, size))) return false;
  vec4 p = texelFetch(uGPosition, pixel, 0);
  position = p.xyz;
  depth = cameraDepth(p.xyz);
  return p.w > 0.5;
}

bool sameSurface(float depthA, float depthB) { return abs(depthA - depthB) < uDepthThreshold; }

// Receivers facing away from the light are shadowed by the facing rule, not by an
// occluder: they make no seeds, take no penumbra and stay out of the mean filter, so the
// terminator is not softened (seed 004 keeps penumbrae apart from self-shadowing).
bool litByFacing(ivec2 pixel) {
  Receiver r;
  return loadReceiver(pixel, r) && !facesAwayFromLight(r);
}
