// The sun disc's geometry for physical_sky.frag's SKYIG_SUN_DISC variant: one quad in the plane
// of the sky around the airless sun, its half-width the tangent of the cone the refracted disc
// can fall in (frameAngles.z, its cosine) plus 5%, so every pixel whose centre lies in the cone
// is covered. Projected by the inverse of the channel's eq. 22 (FrameBlock.ndcToWorld) with
// w = depth along the view axis, so corners behind the eye clip (as render/passes/night/moon.vert). Each
// corner carries its direction: interpolated perspective-correctly over the quad's plane, it is
// the view ray of the pixel, as the full-screen triangle's is.
#include "render/glsl/uniforms.h"

uniform vec3 sunDirectionP;  // unit, ENU, airless
uniform vec3 frameAngles;    // z: cos of the cone the refracted disc falls in

out vec3 vViewRay;

void main() {
  vec3 s = sunDirectionP;
  vec3 up = abs(s.z) < 0.999 ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
  vec3 right = normalize(cross(s, up));
  vec3 top = cross(right, s);
  float c = clamp(frameAngles.z, 0.5, 1.0);
  float halfSize = 1.05 * sqrt(1.0 - c * c) / c;
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, gl_VertexID < 2 ? -1.0 : 1.0);
  vec3 world = s + halfSize * (corner.x * right + corner.y * top);
  vViewRay = world;
  vec3 p = inverse(mat3(ndcToWorld)) * world;
  gl_Position = vec4(p.xy, 0.0, p.z);
}
