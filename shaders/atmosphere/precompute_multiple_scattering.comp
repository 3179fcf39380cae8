// GPU precomputation, step 4c (per order n >= 2): the radiance of order n into
// delta_multiple, added to the scattering table divided by the Rayleigh phase function
// (paper section 4, "Angular precision": C* = S_R[L0] + S[L+] / P_R).
#include "atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
layout(binding = 0) uniform sampler2D transmittance_texture;
layout(binding = 5) uniform sampler3D scattering_density_texture;
layout(binding = 0, rgba32f) uniform writeonly image3D delta_multiple_out;
layout(binding = 2, rgba32f) uniform image3D scattering_accumulated;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(texel, imageSize(delta_multiple_out)))) {
    return;
  }
  Float nu;
  vec4 radiance = computeMultipleScatteringTexel(atm, transmittance_texture,
                                                 scattering_density_texture,
                                                 vec3(texel) + vec3(0.5), nu);
  imageStore(delta_multiple_out, texel, radiance);
  imageStore(scattering_accumulated, texel,
             imageLoad(scattering_accumulated, texel) + radiance / rayleighPhaseFunction(nu));
}
