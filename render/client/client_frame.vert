// The client-frame composite: one triangle covering the client's viewport (as render/glsl/fullscreen.vert)
// at the depth of the client's far plane, so that with the client's depth test (GL_LEQUAL at 1 for
// standard depth, GL_GEQUAL at 0 for reverse-Z) the sky lands only where nothing was drawn.
// farNdcZ: 1 or -1, window depth 1 or 0 under GL's default clip control and depth range, which
// ClientFrameRenderer sets for the draw (the client's own are restored after it).
uniform float farNdcZ;

void main() {
  vec2 ndc = vec2(gl_VertexID == 1 ? 3.0 : -1.0, gl_VertexID == 2 ? 3.0 : -1.0);
  gl_Position = vec4(ndc, farNdcZ, 1.0);
}
