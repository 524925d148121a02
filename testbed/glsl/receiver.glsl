// Shared by every technique's screen pass: the receiver at this pixel from the G-buffer,
// its position in the light's shadow-map space, and the rule that receivers facing away
// from the light are shadowed. Bound by bindReceiverInputs() (render/receiver_inputs.h).
#include "testbed/glsl/light.glsl"

uniform sampler2D uGPosition;  // xyz world position, w = coverage
uniform sampler2D uGNormal;    // the triangle's unit normal, facing the camera
uniform float uFacingLimit;    // sin of the least incidence that counts as lit (scene/view.h)

struct Receiver {
  vec3 position;
  vec3 normal;
};

bool loadReceiver(ivec2 pixel, out Receiver r) {
  vec4 p = texelFetch(uGPosition, pixel, 0);
  r.position = p.xyz;
  r.normal = texelFetch(uGNormal, pixel, 0).xyz;
  return p.w > 0.5;
}

// Unit vector from the receiver towards the light.
vec3 towardsLight(vec3 position) {
  return uLightOrthographic == 1 ? -uLightDirection : normalize(uLightPosition - position);
}

// The facing rule (kFacingLimit in scene/view.h): facing away from the light, or meeting it
// at less than a degree, is shadow.
bool facesAwayFromLight(Receiver r) { return dot(r.normal, towardsLight(r.position)) <= uFacingLimit; }

// The one convention for receivers outside the light's frustum, on any of its six sides
// (beside the map, in front of the near plane, beyond the far plane) or behind a spot
// light: they are in shadow, in every technique and in the ground truths alike. lightSpace()
// sends all of them to kOutsideLight, beyond the map's border (depth 0: every shadow-map
// lookup there reads shadow) and beyond the far plane, so a technique that only looks up
// the map follows the convention without a test of its own; one whose map cannot say so
// (clamped moments, silhouette points) asks insideLightFrustum(). The CPU twin is
// insideLightFrustum() in scene/view.h (the ray caster's).
const vec3 kOutsideLight = vec3(-1.0, -1.0, 2.0);

bool insideLightFrustum(vec3 light) {
  return all(greaterThanEqual(light, vec3(0.0))) && all(lessThanEqual(light, vec3(1.0)));
}

// Shadow-map coordinates: xy in [0,1] across the map, z the light depth in [0,1] as the
// depth buffer stores it; kOutsideLight outside the frustum of `lightViewProjection` (a
// map's world → clip transform: a cascade's), or of the light's in the second form.
vec3 lightSpace(mat4 lightViewProjection, vec3 position) {
  vec4 clip = lightViewProjection * vec4(position, 1.0);
  if (!(clip.w > 0.0)) return kOutsideLight;
  vec3 light = lightCoordinatesOfClip(clip);
  return insideLightFrustum(light) ? light : kOutsideLight;
}
vec3 lightSpace(vec3 position) { return lightSpace(uLightViewProjection, position); }
