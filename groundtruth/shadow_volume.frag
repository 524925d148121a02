#version 450 core
// Counting without depth-buffer precision: a volume face counts only if it lies behind the
// receiver seen at this pixel (depth-fail) or in front of it (depth-pass), as +weight where
// the ray leaves a volume (depth-fail) or enters it (depth-pass), -weight otherwise, summed by
// additive blending. The depth test runs first (depth-pass culls with the G-buffer's
// depth, conservatively offset); the shader's exact test (volume_face.glsl) alone decides.
// Both modes run the same test and keep complementary faces, so where the eye is in no
// volume their counts agree exactly.
#include "testbed/glsl/receiver.glsl"
#include "groundtruth/volume_face.glsl"

layout(early_fragment_tests) in;
layout(location = 0) out float outCount;

layout(location = 0) flat in vec4 vPlane;
layout(location = 1) flat in float vLightCap;
layout(location = 2) flat in float vWeight;  // 1, or 2 for a side two volumes share
uniform vec3 uCameraPosition;
uniform float uTieTolerance;
uniform int uDepthPass;  // 1: count the faces in front of the receiver, 0: those behind it

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  bool behind = volumeFaceBehind(vPlane, vLightCap > 0.5, uCameraPosition, r.position, uTieTolerance);
  bool depthPass = uDepthPass == 1;
  if (behind == depthPass) discard;
  // Seen from outside (front face) the ray enters the volume there.
  outCount = gl_FrontFacing == depthPass ? vWeight : -vWeight;
}
