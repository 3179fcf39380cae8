// The moon pass's geometry: one quad in the plane of the sky around the disc as seen (refracted),
// a little larger than the disc so the anti-aliased limb fits, projected by the channel's
// inverse eq. 22 (worldToNdc); w = depth along the view axis, so corners behind the eye clip.
#include "render/glsl/uniforms.h"

uniform vec3 moonCentreSeen;  // ENU unit vector
uniform vec3 quadRight;       // unit vectors spanning the plane of the sky at the moon
uniform vec3 quadUp;
uniform float quadHalfSize;   // tangent of the quad's half-width
uniform mat3 worldToNdc;      // inverse of FrameBlock.ndcToWorld

void main() {
  vec2 corner = vec2((gl_VertexID & 1) == 0 ? -1.0 : 1.0, gl_VertexID < 2 ? -1.0 : 1.0);
  vec3 world = moonCentreSeen + quadHalfSize * (corner.x * quadRight + corner.y * quadUp);
  vec3 p = worldToNdc * world;
  gl_Position = vec4(p.xy, 0.0, p.z);
}
