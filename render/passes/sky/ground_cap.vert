// The directions below the horizon for physical_sky.frag's SKYIG_GROUND variant: a fan of
// groundCap.z triangles from the nadir to a ring at elevation asin(groundCap.x), a little above
// the horizon's (the fragment stage discards the rays that miss the ground, so the ring only has
// to enclose the horizon: the fan's straight edges cut inside the ring by at most
// (2 pi / segments)^2 / 8 radians). Local east-north-up frame, the planet's centre straight
// below (atmosphere/physical_camera.h). Projected by the inverse of the channel's eq. 22 with
// w = depth along the view axis, so what lies behind the eye clips (as render/passes/night/moon.vert); each
// corner carries its direction, interpolated perspective-correctly into the pixel's view ray.
#include "render/glsl/uniforms.h"

uniform vec3 groundCap;  // sin and cos of the ring's elevation, number of triangles

out vec3 vViewRay;

void main() {
  int corner = gl_VertexID % 3;
  vec3 d = vec3(0.0, 0.0, -1.0);
  if (corner != 0) {
    float a = 6.283185307179586 * float(gl_VertexID / 3 + corner - 1) / groundCap.z;
    d = vec3(groundCap.y * cos(a), groundCap.y * sin(a), groundCap.x);
  }
  vViewRay = d;
  vec3 p = inverse(mat3(ndcToWorld)) * d;
  gl_Position = vec4(p.xy, 0.0, p.z);
}
