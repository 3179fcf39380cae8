// The packed scattering tables (physics/atmosphere/rendering_rec709.glsl) at this frame's radius and
// u_mu_s, as a 2D table over (nu index, mu row): with the camera inside the atmosphere r and
// mu_s are the same for every pixel, so physical_sky.frag reads this with one bilinear 2D
// lookup per table instead of two trilinear 3D ones and a blend by hand. The result is the
// same: multilinear interpolation is separable, and texel (i, j) holds exactly what the 3D
// lookup blends at nu index i and mu row j (Bruneton & Neyret 2008, section 4 parameterisation).
#include "render/glsl/bindings.h"

layout(binding = SKYIG_UNIT_SCATTERING) uniform sampler3D scatteringPacked;
layout(binding = SKYIG_UNIT_SINGLE_MIE) uniform sampler3D singleMieRG;
uniform vec3 sliceCoords;  // u_mu_s, u_r, number of nu texels

layout(location = SKYIG_OUTPUT_SLICE_SCATTERING) out vec4 outScattering;
layout(location = SKYIG_OUTPUT_SLICE_SINGLE_MIE) out vec4 outSingleMie;

void main() {
  vec3 uvw = vec3((floor(gl_FragCoord.x) + sliceCoords.x) / sliceCoords.z,
                  gl_FragCoord.y / float(textureSize(scatteringPacked, 0).y), sliceCoords.y);
  outScattering = texture(scatteringPacked, uvw);
  outSingleMie = texture(singleMieRG, uvw);
}
