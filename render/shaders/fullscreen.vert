// boreas: one triangle that covers the screen, for the sky and the tone mapper; v_ndc is
// the pixel's normalized device position.
out vec2 v_ndc;

void main() {
  vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1));
  v_ndc = p;
  gl_Position = vec4(p, 1.0, 1.0);
}
