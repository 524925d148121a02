// The tap pattern of both PCSS grids (pcss.frag): k×k taps evenly over the square of
// half width `radius` (uv) around the receiver, each at its cell's centre. A helper file
// of the plugin's own, so testbed_add_plugin's SHADERS must list it (else the build stops).
vec2 gridTapOffset(int x, int y, int k, float radius) {
  return ((vec2(x, y) + 0.5) / float(k) * 2.0 - 1.0) * radius;
}
