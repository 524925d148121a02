// The light as every screen pass sees it: its transforms, depth range, frustum size and the
// size of the area light the soft reference samples, with the helpers a technique needs to
// reason in light space. Set for every technique by bindReceiverInputs()
// (render/receiver_inputs.h) from the frame's LightTransforms (scene/view.h); the
// area-light model is docs/writing-a-technique.md "The light in GLSL".
uniform mat4 uLightViewProjection;   // world → light clip space (the shadow map's)
uniform mat4 uLightView;             // world → light view space (looking down −z)
uniform mat4 uLightProjection;       // light view → clip space
uniform mat4 uLightViewInverse;
uniform mat4 uLightProjectionInverse;
uniform vec3 uLightPosition;   // spot: the eye; directional: the orthographic eye
uniform vec3 uLightDirection;  // the direction light travels (unit)
uniform int uLightOrthographic;
uniform float uLightNear;      // the depth range, as view depths along uLightDirection
uniform float uLightFar;
uniform float uLightFov;       // spot: the square frustum's full angle in radians; else 0
uniform float uLightExtent;    // directional: half size of the square footprint; else 0
// The area light of the soft reference (groundtruth/shadow_volumes.cpp): spot, a disk of
// this radius in world units around uLightPosition facing the target; directional, the
// sun's angular radius in radians. 0: a point light (hard shadows).
uniform float uLightRadius;

// Shadow-map coordinates from light clip coordinates: xy in [0,1] across the map, z the
// depth as the depth buffer stores it.
vec3 lightCoordinatesOfClip(vec4 clip) { return clip.xyz / clip.w * 0.5 + 0.5; }

// Shadow-map coordinates of a world position WITHOUT clamping or the outside-the-frustum
// convention (lightSpace() in receiver.glsl applies that): a blocker search or a gradient
// may step beside the map. Meaningless behind a spot light (view depth ≤ 0). The first
// form takes the map's world → clip transform (a cascade's), the second the light's.
vec3 lightCoordinates(mat4 lightViewProjection, vec3 world) {
  return lightCoordinatesOfClip(lightViewProjection * vec4(world, 1.0));
}
vec3 lightCoordinates(vec3 world) { return lightCoordinates(uLightViewProjection, world); }

// World size of one texel along a map's x and y at view depth `viewDepth` from the light,
// for a map of `mapSize` texels made with the projection `lightProjection` (orthographic or
// perspective, cropped or not: the view is rigid, so the projection alone scales):
// 2·w / (P₀₀·N) and 2·w / (P₁₁·N), w the clip w at that depth (1 orthographic, the depth
// perspective). The C++ twin is texelWorldSize() in technique/light_crop.h.
vec2 texelWorldSize(mat4 lightProjection, ivec2 mapSize, float viewDepth) {
  float w = -lightProjection[2][3] * viewDepth + lightProjection[3][3];
  return 2.0 * w / (vec2(lightProjection[0][0], lightProjection[1][1]) * vec2(mapSize));
}

// The view depth (world units along uLightDirection from uLightPosition) of a world point.
float lightViewDepthOf(vec3 world) { return dot(world - uLightPosition, uLightDirection); }

// The view depth of a depth as the shadow map stores it (in [0,1]): the inverse of the
// projection's depth mapping. Perspective (glm::perspective, NDC z in [−1,1]):
// z_ndc = (f+n)/(f−n) − 2fn/((f−n)·d), so d = 2fn / (f+n − z_ndc·(f−n)); orthographic: linear.
float linearizeLightDepth(float stored) {
  float n = uLightNear, f = uLightFar;
  if (uLightOrthographic == 1) return n + stored * (f - n);
  float ndc = stored * 2.0 - 1.0;
  return 2.0 * f * n / (f + n - ndc * (f - n));
}

// Receiver plane depth bias (Isidoro, "Shadow Mapping: GPU-based Tips and Techniques",
// GDC 2006, "Receiver Plane Depth Bias"): over a planar receiver the stored depth z is
// affine in the map's (u, v), so a filter tap at uv + offset compares against
// z + dot(gradient, offset) instead of the centre's z. `dx`, `dy`: the light coordinates'
// changes along two directions on the receiver (screen derivatives dFdx/dFdy, or tangent
// steps); returns (∂z/∂u, ∂z/∂v) by inverting the 2×2 Jacobian ∂(u,v)/∂(x,y). Infinite
// for a receiver seen edge-on by the light (callers clamp; the facing rule shadows those).
vec2 receiverPlaneDepthGradientFromSteps(vec3 dx, vec3 dy) {
  vec2 gradient = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z);
  return gradient / (dx.x * dy.y - dx.y * dy.x);
}

// The same from the receiver's plane itself (its G-buffer position and normal), which a
// deferred screen pass has exactly; screen derivatives would mix neighbouring surfaces at
// silhouettes. A projective map sends planes to planes, so the light coordinates of the
// plane are affine in (u, v) for a spot light too: the finite steps give the exact gradient
// (up to rounding), whatever their length.
// The first form takes the map's world → clip transform (a cascade's), the second the light's.
vec2 receiverPlaneDepthGradient(mat4 lightViewProjection, vec3 position, vec3 normal) {
  vec3 helper = abs(normal.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0);
  vec3 t1 = normalize(cross(normal, helper));
  vec3 t2 = cross(normal, t1);
  // Steps small against the distance to the light keep both points in front of a spot light.
  float reach = 0.01 * (uLightOrthographic == 1 ? uLightExtent : lightViewDepthOf(position));
  vec3 centre = lightCoordinates(lightViewProjection, position);
  return receiverPlaneDepthGradientFromSteps(lightCoordinates(lightViewProjection, position + reach * t1) - centre,
                                             lightCoordinates(lightViewProjection, position + reach * t2) - centre);
}
vec2 receiverPlaneDepthGradient(vec3 position, vec3 normal) {
  return receiverPlaneDepthGradient(uLightViewProjection, position, normal);
}

// The receiver's depth at the tap `offset` (in uv) from its own coordinates `light`.
float receiverPlaneDepth(vec3 light, vec2 gradient, vec2 offset) { return light.z + dot(gradient, offset); }
