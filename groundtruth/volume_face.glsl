// Whether a volume face lies behind the receiver seen at this pixel, without depth-buffer
// precision: the camera ray crosses the face's plane before the receiver exactly when
// camera and receiver lie on opposite sides of it, an exact test in world space. A
// receiver within the tie tolerance of a light cap's plane (the cap on its own surface)
// counts the cap as behind it, so lit surfaces are outside their own volumes; side faces
// are decided by sign alone. Every counting mode (shadow_volume.frag's blended counts,
// shadow_volume_stencil.frag's stencil) asks this one test, so their counts agree.
bool volumeFaceBehind(vec4 plane, bool lightCap, vec3 camera, vec3 receiver, float tieTolerance) {
  float atCamera = dot(plane.xyz, camera) + plane.w;
  float atReceiver = dot(plane.xyz, receiver) + plane.w;
  bool onOwnCap = lightCap && abs(atReceiver) <= tieTolerance;
  return onOwnCap || (atCamera > 0.0) == (atReceiver > 0.0);
}
