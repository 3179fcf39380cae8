// GPU precomputation, step 4c (per order n >= 2): the radiance of order n into
// delta_multiple, added to the scattering table divided by the Rayleigh phase function
// (paper section 4, "Angular precision": C* = S_R[L0] + S[L+] / P_R). The integral is
// computeMultipleScattering's (multiple_scattering.glsl), with the density table read at its
// own sizes (atm_density), which may be coarser than the others.
#include "common/bindings.h"
#include "atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
// atm with the density table's sizes (GpuPrecomputeOptions::density_divisor; = atm by default).
uniform AtmosphereParameters atm_density;
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
layout(binding = SKYIG_UNIT_DELTA_DENSITY) uniform sampler3D scattering_density_texture;
layout(binding = SKYIG_IMAGE_DELTA_MULTIPLE, rgba32f) uniform writeonly image3D delta_multiple_out;
layout(binding = SKYIG_IMAGE_SCATTERING, rgba32f) uniform image3D scattering_accumulated;

// computeMultipleScattering's integral, with the density looked up at its own table sizes.
vec4 integrand(Float r, Float mu, Float mu_s, Float nu, Float d, bool ray_r_mu_intersects_ground) {
  Float r_d = radiusAtDistance(atm, r, mu, d);
  Float mu_d = atmClampCosine((r * mu + d) / r_d);
  Float mu_s_d = atmClampCosine((r * mu_s + d * nu) / r_d);
  return lookupScattering(atm_density, scattering_density_texture, r_d, mu_d, mu_s_d, nu,
                          ray_r_mu_intersects_ground) *
         transmittanceAlongRay(atm, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground);
}

// The first radius (z) of this dispatch: the pass runs a slice of radii at a time, so that a
// precompute can stop between slices (render/passes/atmosphere_gpu_precompute.cpp).
uniform int z_offset;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, z_offset);
  if (any(greaterThanEqual(texel, imageSize(delta_multiple_out)))) {
    return;
  }
  Float r;
  Float mu;
  Float mu_s;
  Float nu;
  bool ray_r_mu_intersects_ground;
  rMuMuSNuFromScatteringFragCoord(atm, vec3(texel) + vec3(0.5), r, mu, mu_s, nu,
                                  ray_r_mu_intersects_ground);
  Float dx = distanceToNearestAtmosphereBoundary(atm, r, mu, ray_r_mu_intersects_ground) /
             Float(ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES);
  vec4 radiance = vec4(0.0);
  vec4 previous = integrand(r, mu, mu_s, nu, 0.0, ray_r_mu_intersects_ground);
  for (int i = 1; i <= ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES; ++i) {
    vec4 current = integrand(r, mu, mu_s, nu, Float(i) * dx, ray_r_mu_intersects_ground);
    radiance += exponentialStepIntegral4(previous, current, dx);
    previous = current;
  }
  imageStore(delta_multiple_out, texel, radiance);
  imageStore(scattering_accumulated, texel,
             imageLoad(scattering_accumulated, texel) + radiance / rayleighPhaseFunction(nu));
}
