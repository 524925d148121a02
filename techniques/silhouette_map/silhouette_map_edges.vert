#version 450 core
// Conservative rasterization of the silhouette edges into the silhouette map (viewport
// (N + 1)², silhouette space, see silhouette_map.glsl) by vertex pulling: the 4 corners of
// each edge's quad (drawn indexed as two triangles) around the projected segment, widened
// and lengthened by kMargin texels on every side. Any texel the segment touches has its
// centre within √2/2 of the segment, so within √2/2 of it along and across, and it is
// rasterized (the paper's "thin quads"; the fragment shader drops the extras). Only touched texels get a point
// (silhouettePoint), so any margin over √2/2 writes the same map: 0.75 keeps the texel
// centres 0.04 texels clear of the quad's edges, where the rasterizer's rule could drop
// them, and shades a quarter (long edges) to a third (short ones) fewer fragments than a
// margin of 1.
#include "testbed/glsl/units.glsl"
layout(std430, binding = kSilhouetteEdgesBufferBinding) readonly buffer Edges { vec4 endpoints[]; };
uniform mat4 uLightViewProjection;
uniform float uMapSize;  // N, the depth map's side
layout(location = 0) flat out vec3 vA;       // silhouette-space xy, light depth z (as the depth map stores it)
layout(location = 1) flat out vec3 vB;

vec3 silhouetteSpace(vec4 clip) {
  vec3 ndc = clip.xyz / clip.w;
  return vec3((ndc.xy * 0.5 + 0.5) * uMapSize + 0.5, ndc.z * 0.5 + 0.5);
}

void main() {
  int edge = gl_VertexID / 4;
  int corner = gl_VertexID % 4;
  vec4 a = uLightViewProjection * vec4(endpoints[2 * edge].xyz, 1.0);
  vec4 b = uLightViewProjection * vec4(endpoints[2 * edge + 1].xyz, 1.0);
  // Clip to the near plane (z ≥ −w) so edges reaching behind a spot light project sanely.
  float da = a.z + a.w, db = b.z + b.w;
  if (da < 0.0 && db < 0.0) {
    gl_Position = vec4(-2.0, -2.0, 0.0, 1.0);  // all four alike: no area, no fragment
    vA = vB = vec3(-1.0);
    return;
  }
  if (da < 0.0) a = mix(a, b, da / (da - db));
  else if (db < 0.0) b = mix(b, a, db / (db - da));
  vA = silhouetteSpace(a);
  vB = silhouetteSpace(b);
  vec2 d = vB.xy - vA.xy;
  float len = length(d);
  const float kMargin = 0.75;
  vec2 along = kMargin * (len > 1e-6 ? d / len : vec2(1.0, 0.0));
  vec2 across = vec2(-along.y, along.x);
  vec2 p = (corner == 0 || corner == 3 ? vA.xy - along : vB.xy + along) + (corner < 2 ? -across : across);
  gl_Position = vec4(p / (uMapSize + 1.0) * 2.0 - 1.0, 0.0, 1.0);
}
