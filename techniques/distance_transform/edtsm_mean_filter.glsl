// What both forms of EDTSM's edge-aware separable mean filter (EDTSM* §3.4) share: the
// window is the user's world-space width seen at the receiver's distance (eqs. 9–10:
// w_screen = w · z_screen / z_eye with z_screen = 1 / (2 tan(fov_y / 2)), a fraction of the
// screen height), so the blur keeps its world size as the camera moves; only neighbours on
// the same surface and facing the light take part. edtsm_mean_filter.frag filters one pixel,
// edtsm_mean_filter.comp four along a line; both add a pixel's taps in the same order.
// EDTSM*: Macedo & Apolinário, "Improved anti-aliasing for Euclidean distance transform
// shadow mapping", Computers & Graphics 71 (2018).
#include "techniques/distance_transform/edtsm_screen.glsl"

uniform sampler2D uIntensity;   // (intensity, camera depth or −1)
uniform float uFilterWidth;     // world units
uniform float uScreenDistance;  // z_screen
uniform vec3 uCameraPosition;
uniform int uMaxRadius;         // pixels

// The window's half width in pixels at receiver `r`.
int filterRadius(Receiver r) {
  float heightPx = float(textureSize(uGPosition, 0).y);
  float widthPx = uFilterWidth * uScreenDistance / distance(r.position, uCameraPosition) * heightPx;
  return min(int(floor(0.5 * widthPx)), uMaxRadius);
}

// Whether `tap` takes part in the mean around a receiver at camera depth `centreDepth`:
// taps off the receivers, facing away (depth −1, also off the screen: fetchWithDepth) or on
// another surface do not.
bool filterTakes(float centreDepth, vec2 tap) { return !(tap.y < 0.0) && sameSurface(centreDepth, tap.y); }
