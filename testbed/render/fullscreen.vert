#version 450 core
// One triangle covering the screen; fragment shaders read the G-buffer by gl_FragCoord.
void main() {
  const vec2 corners[3] = vec2[](vec2(-1, -1), vec2(3, -1), vec2(-1, 3));
  gl_Position = vec4(corners[gl_VertexID], 0.0, 1.0);
}
