// Shared by every technique's screen pass: the receiver at this pixel from the G-buffer,
// its position in the light's shadow-map space, and the rule that receivers facing away
// from the light are shadowed. Bound by bindReceiverInputs() (render/shadow_map_pass.h).
uniform sampler2D uGPosition;  // xyz world position, w = coverage
uniform sampler2D uGNormal;    // the triangle's unit normal, facing the camera
uniform mat4 uLightViewProjection;
uniform vec3 uLightPosition;
uniform vec3 uLightDirection;  // the direction light travels
uniform int uLightOrthographic;

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

bool facesAwayFromLight(Receiver r) { return dot(r.normal, towardsLight(r.position)) <= 0.0; }

// Shadow-map coordinates: xy in [0,1] across the map, z the light depth in [0,1] as the
// depth buffer stores it. Points behind a spot light get xy outside the map (→ shadow).
vec3 lightSpace(vec3 position) {
  vec4 clip = uLightViewProjection * vec4(position, 1.0);
  if (clip.w <= 0.0) return vec3(-1.0, -1.0, 1.0);
  return clip.xyz / clip.w * 0.5 + 0.5;
}
