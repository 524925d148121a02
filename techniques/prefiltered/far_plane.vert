#version 450 core
// A full-screen triangle at light depth 1: drawn with moments.frag before the scene it
// clears the map to the technique's own moments of the far plane (no CPU copy of the
// encodings).
layout(location = 0) out float vLightDepth;
void main() {
  const vec2 corners[3] = vec2[](vec2(-1, -1), vec2(3, -1), vec2(-1, 3));
  vLightDepth = 1.0;
  gl_Position = vec4(corners[gl_VertexID], 0.0, 1.0);
}
