#version 450 core
// One silhouette point per texel (Chan's notes): pick it by the diagonal rules, drop edges
// the light does not see (behind all four corner depth samples), write the point as an
// offset in [0,1]² of the texel. Later edges overwrite earlier ones, as in the paper.
// Chan's notes: Eric Chan (MIT), "Shadow Silhouette Maps", course notes on Sen et al.'s maps.
#include "techniques/silhouette_map/silhouette_corners.glsl"
#include "techniques/silhouette_map/silhouette_map.glsl"

layout(location = 0) flat in vec3 vA;
layout(location = 1) flat in vec3 vB;
uniform float uOcclusionBias;
layout(location = 0) out vec2 outPoint;

void main() {
  ivec2 texel = ivec2(floor(gl_FragCoord.xy));
  vec3 origin = vec3(vec2(texel), 0.0);
  vec3 point;
  if (!silhouettePoint(vA - origin, vB - origin, point)) discard;
  if (all(equal(cornerShadowTests(texel, point.z, uOcclusionBias), vec4(0.0)))) discard;
  outPoint = point.xy;
}
