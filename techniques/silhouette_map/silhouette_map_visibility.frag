#version 450 core
// The final pass (seed 003): the four depth tests at the corners of the receiver's
// silhouette texel; where they agree (non-silhouette pixel) they are the answer, else the
// skewed quadrant of the five silhouette points picks the corner whose test decides.
#include "testbed/glsl/receiver.glsl"
#include "testbed/glsl/shadow_test.glsl"
#include "techniques/silhouette_map/silhouette_map.glsl"

uniform sampler2D uSilhouetteMap;  // RG: the point's offset in its texel, (N + 1)²
uniform float uBias;
layout(location = 0) out float outVisibility;

// A texel's point in the coordinates of the texel `offset` away from it; the centre for
// texels outside the map (no silhouette there).
vec2 pointAt(ivec2 texel, ivec2 offset) {
  ivec2 q = texel + offset;
  ivec2 size = textureSize(uSilhouetteMap, 0);
  vec2 local = any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)) ? vec2(0.5) : texelFetch(uSilhouetteMap, q, 0).rg;
  return local + vec2(offset);
}

void main() {
  Receiver r;
  if (!loadReceiver(ivec2(gl_FragCoord.xy), r)) discard;
  vec3 light = lightSpace(r.position);
  // Outside the light's frustum: shadow (glsl/receiver.glsl's convention).
  if (facesAwayFromLight(r) || !insideLightFrustum(light)) {
    outVisibility = 0.0;
    return;
  }
  vec2 w = light.xy * vec2(uShadowMapSize) + 0.5;
  ivec2 texel = ivec2(floor(w));
  float s[4];
  for (int c = 0; c < 4; ++c) s[c] = shadowTestTexel(texel - 1 + ivec2(c & 1, c >> 1), light.z, uBias);
  if (s[0] == s[1] && s[0] == s[2] && s[0] == s[3]) {
    outVisibility = s[0];
    return;
  }
  int corner = quadrantCorner(pointAt(texel, ivec2(0)), pointAt(texel, ivec2(1, 0)), pointAt(texel, ivec2(0, 1)),
                              pointAt(texel, ivec2(-1, 0)), pointAt(texel, ivec2(0, -1)), w - vec2(texel));
  outVisibility = s[corner];
}
