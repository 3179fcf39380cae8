// The directions near the horizon for physical_sky.frag's SKYIG_HORIZON_EDGE variant: a ring of
// horizonStrip.w quads between the elevations asin(horizonStrip.x) and asin(horizonStrip.z),
// which the pass places a pixel and a half either side of the horizon's, so that the strip holds
// every pixel the horizon crosses (the fragment stage discards the others). Each quad's edges are
// chords, whose great circles leave the ring by e (1 - cos(pi / segments)), e the ring's
// elevation: 1e-4 deg for 256 segments, far inside the margin. Projected as ground_cap.vert does
// (the local east-north-up frame; w = depth along the view axis, so what lies behind the eye
// clips), each corner carrying its direction into the pixel's view ray.
#include "render/glsl/uniforms.h"

uniform vec4 horizonStrip;  // sin and cos of the lower ring's elevation, sin of the upper's, segments

out vec3 vViewRay;

void main() {
  // Two triangles a quad: corners (lower, i), (upper, i), (lower, i + 1); (upper, i), (upper, i + 1), (lower, i + 1).
  const int kRing[6] = int[6](0, 1, 0, 1, 1, 0);
  const int kStep[6] = int[6](0, 0, 1, 0, 1, 1);
  int corner = gl_VertexID % 6;
  float a = 6.283185307179586 * float(gl_VertexID / 6 + kStep[corner]) / horizonStrip.w;
  float s = kRing[corner] == 0 ? horizonStrip.x : horizonStrip.z;
  float c = kRing[corner] == 0 ? horizonStrip.y : sqrt(max(1.0 - horizonStrip.z * horizonStrip.z, 0.0));
  vec3 d = vec3(c * cos(a), c * sin(a), s);
  vViewRay = d;
  vec3 p = inverse(mat3(ndcToWorld)) * d;
  gl_Position = vec4(p.xy, 0.0, p.z);
}
