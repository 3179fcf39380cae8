// GPU precomputation, step 4a (per order n >= 2): the scattering density J of order n from
// the radiance of order n-1 and the ground irradiance of order n-2.
#include "atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
uniform int scattering_order;
layout(binding = 0) uniform sampler2D transmittance_texture;
layout(binding = 1) uniform sampler3D single_rayleigh_texture;
layout(binding = 2) uniform sampler3D single_mie_texture;
layout(binding = 3) uniform sampler3D multiple_texture;
layout(binding = 4) uniform sampler2D irradiance_texture;
layout(binding = 0, rgba32f) uniform writeonly image3D density_out;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(texel, imageSize(density_out)))) {
    return;
  }
  imageStore(density_out, texel,
             computeScatteringDensityTexel(atm, transmittance_texture, single_rayleigh_texture,
                                           single_mie_texture, multiple_texture,
                                           irradiance_texture, vec3(texel) + vec3(0.5),
                                           scattering_order));
}
