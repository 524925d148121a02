#version 450 core
// The final pass (Sen, Cammarano & Hanrahan 2003, §3): the four depth tests at the corners
// of the receiver's silhouette texel; where they agree (non-silhouette pixel) they are the
// answer, else the skewed quadrant of the five silhouette points picks the corner whose
// test decides. Drawn edge-split (testbed/glsl/screen_pass.glsl): a draw of every pixel
// answers where the corners agree, the silhouette pixels alone read the silhouette map.
// Sen, Cammarano & Hanrahan, "Shadow Silhouette Maps", ACM TOG 22(3) (SIGGRAPH 2003).
#include "testbed/glsl/receiver.glsl"
#include "techniques/silhouette_map/silhouette_corners.glsl"
#include "techniques/silhouette_map/silhouette_map.glsl"

uniform sampler2D uSilhouetteMap;  // RG: the point's offset in its texel, (N + 1)²
uniform float uBias;

// A texel's point in the coordinates of the texel `offset` away from it; the centre for
// texels outside the map (no silhouette there).
vec2 pointAt(ivec2 texel, ivec2 offset) {
  ivec2 q = texel + offset;
  ivec2 size = textureSize(uSilhouetteMap, 0);
  vec2 local = any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)) ? vec2(0.5) : texelFetch(uSilhouetteMap, q, 0).rg;
  return local + vec2(offset);
}

// The four depth tests at the corners of the receiver's silhouette texel (inside the
// light's frustum: screen_pass.glsl answers outside). True where they agree and so decide
// alone (v = that test).
bool cornerTests(vec3 light, out vec4 s, out ivec2 texel, out vec2 w, out float v) {
  w = light.xy * vec2(uShadowMapSize) + 0.5;
  texel = ivec2(floor(w));
  s = cornerShadowTests(texel, light.z, uBias);
  v = s[0];
  return all(equal(s, vec4(v)));
}

bool screenClassify(ivec2 pixel, Receiver r, vec3 light, out float v) {
  vec4 s;
  ivec2 texel;
  vec2 w;
  return cornerTests(light, s, texel, w, v);
}

float screenVisibility(ivec2 pixel, Receiver r, vec3 light) {
  vec4 s;
  float v;
  ivec2 texel;
  vec2 w;
  if (cornerTests(light, s, texel, w, v)) return v;
  int corner = quadrantCorner(pointAt(texel, ivec2(0)), pointAt(texel, ivec2(1, 0)), pointAt(texel, ivec2(0, 1)),
                              pointAt(texel, ivec2(-1, 0)), pointAt(texel, ivec2(0, -1)), w - vec2(texel));
  return s[corner];
}

#include "testbed/glsl/screen_pass.glsl"
