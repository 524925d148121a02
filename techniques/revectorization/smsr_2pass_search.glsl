// smsr-2pass, pass 2's search (Bondarev 2014, "Second pass"): for a lit pixel with an
// entering discontinuity, search the screen-space discontinuity map along the two light
// axes for the edge's ends. The screen step that reaches the neighbouring shadow-map texel
// comes from the receiver's local plane: the pixel-to-light-uv Jacobian from the G-buffer
// positions of the pixel's neighbours, inverted. A step ends the edge (end found) on a
// shadowed receiver; it stops without an end off the receivers, on a lit pixel sharing
// no discontinuity direction, or after max_search steps. Shared by the timed pass and the
// ONDS debug view so the view shows exactly what the pass clips.
// Bondarev, "Shadow Map Silhouette Revectorization", poster, I3D 2014.
#include "testbed/glsl/receiver.glsl"
#include "testbed/render/revectorization/revectorization.glsl"

uniform sampler2D uDiscontinuityMap;

vec4 decodeDirections(vec2 rg) {
  ivec2 k = ivec2(round(rg * 4.0));
  return vec4(k.x >= 2, (k.x & 1) == 1, k.y >= 2, (k.y & 1) == 1);
}

int searchScreen(vec2 start, vec2 stepPx, vec4 dOrigin) {
  vec2 size = vec2(textureSize(uDiscontinuityMap, 0));
  vec2 pos = start;
  int n = 1;
  for (int i = 0; i < uMaxSearch; ++i) {
    pos += stepPx;
    if (any(lessThan(pos, vec2(0.0))) || any(greaterThanEqual(pos, size))) return -n;
    vec4 disc = texelFetch(uDiscontinuityMap, ivec2(pos), 0);
    if (disc.a < 0.5) return -n;   // no receiver there
    if (disc.b > 0.5) return n;    // shadowed receiver: the edge's end
    if (dot(decodeDirections(disc.rg), dOrigin) == 0.0) return -n;
    ++n;
  }
  return -n;
}

// Light-space uv of the receiver at pixel q (or of p when q has none).
vec2 lightUvAt(ivec2 q, vec2 fallback) {
  vec4 position = texelFetch(uGPosition, q, 0);
  return position.w > 0.5 ? lightSpace(position.xyz).xy : fallback;
}

// Pass 1 wrote no entering discontinuity here (shadowed, or lit without one): the
// visibility is the shadow test, 1 − b.
bool twoPassNoEdge(vec4 disc) { return disc.b > 0.5 || disc.rg == vec2(0.0); }

// The pixel's sample for the clipping: `s.edge` false means no revectorization, and then
// s.s is the visibility (the shadow test, or lit where no stair can be seen).
RvSample twoPassSample(ivec2 pixel, Receiver r) {
  RvSample s;
  s.edge = false;
  s.d = vec4(0.0);
  s.x = RvAxis(1.0, RV_NO_END);
  s.y = RvAxis(1.0, RV_NO_END);
  vec4 disc = texelFetch(uDiscontinuityMap, pixel, 0);
  s.s = 1.0 - disc.b;
  if (twoPassNoEdge(disc)) return s;
  // d(light texel)/d(pixel), one-sided differences; a neighbour off the receivers falls
  // back to the other side.
  vec2 texels = vec2(uShadowMapSize);
  vec2 uv = lightSpace(r.position).xy;
  vec2 dx = lightUvAt(pixel + ivec2(1, 0), uv) - uv;
  if (dx == vec2(0.0)) dx = uv - lightUvAt(pixel - ivec2(1, 0), uv);
  vec2 dy = lightUvAt(pixel + ivec2(0, 1), uv) - uv;
  if (dy == vec2(0.0)) dy = uv - lightUvAt(pixel - ivec2(0, 1), uv);
  mat2 jacobian = mat2(dx * texels, dy * texels);  // columns: per pixel x, per pixel y
  if (abs(determinant(jacobian)) < 1e-8) return s;
  mat2 inverse_ = inverse(jacobian);  // light texels → pixels
  vec2 stepX = inverse_ * vec2(1.0, 0.0), stepY = inverse_ * vec2(0.0, 1.0);
  // A texel smaller than a pixel has no visible stair to revectorize.
  if (length(stepX) < 1.0 || length(stepY) < 1.0) return s;
  s.d = decodeDirections(disc.rg);
  s.edge = true;
  vec2 start = vec2(pixel) + 0.5;
  vec2 t = uv * texels;
  vec2 p = t - floor(t);
  s.x = rvAxis(searchScreen(start, -stepX, s.d), searchScreen(start, stepX, s.d), p.x);
  s.y = rvAxis(searchScreen(start, -stepY, s.d), searchScreen(start, stepY, s.d), p.y);
  return s;
}
