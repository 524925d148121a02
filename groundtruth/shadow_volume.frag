#version 450 core
// Stencil counting without a depth buffer: a volume face counts only if it lies behind the
// receiver seen at this pixel (depth-fail) or in front of it (depth-pass). The camera ray
// crosses the face's plane before the receiver exactly when camera and receiver lie on
// opposite sides of it, which is an exact test in world space, free of depth-buffer
// precision. A receiver within the tie tolerance of a light cap's plane (the cap on its own
// surface) counts the cap as behind it, so lit surfaces are outside their own volumes; side
// faces are decided by sign alone. Both modes run the same test and keep complementary
// faces, so where the eye is in no volume their counts agree exactly.
#include "testbed/glsl/receiver.glsl"

flat in vec4 vPlane;
flat in float vLightCap;
uniform vec3 uCameraPosition;
uniform float uTieTolerance;
uniform int uDepthPass;  // 1: count the faces in front of the receiver, 0: those behind it

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  float atCamera = dot(vPlane.xyz, uCameraPosition) + vPlane.w;
  float atReceiver = dot(vPlane.xyz, r.position) + vPlane.w;
  bool onOwnCap = vLightCap > 0.5 && abs(atReceiver) <= uTieTolerance;
  bool behind = onOwnCap || (atCamera > 0.0) == (atReceiver > 0.0);
  if (behind == (uDepthPass == 1)) discard;
}
