#version 450 core
// Depth-fail counting without a depth buffer: a volume face counts only if it lies behind
// the receiver seen at this pixel. The camera ray crosses the face's plane before the
// receiver exactly when camera and receiver lie on opposite sides of it, which is an
// exact test in world space, free of depth-buffer precision. A receiver on the plane
// itself (a light cap on its own surface) counts the face as behind it, so lit surfaces
// are outside their own volumes.
#include "testbed/glsl/receiver.glsl"

flat in vec4 vPlane;
uniform vec3 uCameraPosition;
uniform float uTieTolerance;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  float atCamera = dot(vPlane.xyz, uCameraPosition) + vPlane.w;
  float atReceiver = dot(vPlane.xyz, r.position) + vPlane.w;
  bool behind = abs(atReceiver) <= uTieTolerance || (atCamera > 0.0) == (atReceiver > 0.0);
  if (!behind) discard;
}
