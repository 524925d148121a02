#version 450 core
// The plugin fixture's copy of techniques/shadow_map/shadow_map_visibility.frag: same
// visibility as sm, from a shader the plugin embeds itself.
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"

uniform float uBias;
layout(location = 0) out float outVisibility;

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  if (facesAwayFromLight(r)) {
    outVisibility = 0.0;
    return;
  }
  vec3 light = lightSpace(r.position);
  outVisibility = shadowTest(light.xy, light.z, uBias);
}
