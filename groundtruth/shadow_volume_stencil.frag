#version 450 core
// The paper path's count (stencil_counting.h): a fragment survives where its face lies
// behind the receiver, by the exact world-space test that stands in for the depth test's
// comparison (volume_face.glsl), and the two-sided stencil operation then counts it:
// back faces +1, front faces -1 (depth-fail, Carmack's reverse). No colour is written.
// No early fragment tests: the stencil must change only for the fragments kept here.
#include "testbed/glsl/receiver.glsl"
#include "groundtruth/volume_face.glsl"

layout(location = 0) flat in vec4 vPlane;
layout(location = 1) flat in float vLightCap;
layout(location = 2) flat in float vWeight;  // always 1 here: capped depth-fail volumes draw no side twice
uniform vec3 uCameraPosition;
uniform float uTieTolerance;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  if (!volumeFaceBehind(vPlane, vLightCap > 0.5, uCameraPosition, r.position, uTieTolerance)) discard;
}
