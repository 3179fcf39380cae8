// GPU precomputation, step 3: single Rayleigh and Mie scattering into the delta tables, and
// the accumulated tables initialised with them (C* = S_R[L0], C_M = S_M[L0]).
#include "common/bindings.h"
#include "atmosphere/single_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
layout(binding = SKYIG_IMAGE_DELTA_RAYLEIGH, rgba32f) uniform writeonly image3D delta_rayleigh_out;
layout(binding = SKYIG_IMAGE_DELTA_MIE, rgba32f) uniform writeonly image3D delta_mie_out;
layout(binding = SKYIG_IMAGE_SCATTERING, rgba32f) uniform writeonly image3D scattering_out;
layout(binding = SKYIG_IMAGE_SINGLE_MIE, rgba32f) uniform writeonly image3D single_mie_out;
// The first radius (z) of this dispatch: the pass runs a slice of radii at a time, so that a
// precompute can stop between slices (render/passes/atmosphere_gpu_precompute.cpp).
uniform int z_offset;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, z_offset);
  if (any(greaterThanEqual(texel, imageSize(delta_rayleigh_out)))) {
    return;
  }
  vec4 rayleigh;
  vec4 mie;
  computeSingleScatteringTexel(atm, transmittance_texture, vec3(texel) + vec3(0.5), rayleigh,
                               mie);
  imageStore(delta_rayleigh_out, texel, rayleigh);
  imageStore(delta_mie_out, texel, mie);
  imageStore(scattering_out, texel, rayleigh);
  imageStore(single_mie_out, texel, mie);
}
