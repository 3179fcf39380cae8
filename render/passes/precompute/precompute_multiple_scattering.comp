// GPU precomputation, step 4c (per order n >= 2): the radiance of order n into
// delta_multiple, added to the scattering table divided by the Rayleigh phase function
// (paper section 4, "Angular precision": C* = S_R[L0] + S[L+] / P_R). The integral is
// computeMultipleScattering's (multiple_scattering.glsl), with the density table read at its
// own sizes (atm_density), which may be coarser than the others.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
// atm with the density table's sizes (GpuPrecomputeOptions::density_divisor; = atm by default).
uniform AtmosphereParameters atm_density;
layout(binding = SKYIG_UNIT_DELTA_DENSITY) uniform sampler3D scattering_density_texture;
// precompute_ray_transmittance.comp: per sample i of the ray of row (mu, r), texel (i, mu, r),
// the transmittance from the ray's start and (r_d, u_mu, u_r, dx).
layout(binding = SKYIG_UNIT_RAY_TRANSMITTANCE) uniform sampler3D ray_transmittance;
layout(binding = SKYIG_UNIT_RAY_GEOMETRY) uniform sampler3D ray_geometry;
layout(binding = SKYIG_IMAGE_DELTA_MULTIPLE, rgba32f) uniform writeonly image3D delta_multiple_out;
layout(binding = SKYIG_IMAGE_SCATTERING, rgba32f) uniform image3D scattering_accumulated;

// multipleScatteringIntegrand at the sample `sample_texel` (i, mu, r) of the ray: the density
// looked up at its own table sizes, times the transmittance to the point. Only mu_s and nu vary
// along the row, so the lookup's u_mu and u_r and the transmittance come from the ray tables.
vec4 integrand(ivec3 sample_texel, Float r, Float mu_s, Float nu, Float d) {
  vec4 geometry = texelFetch(ray_geometry, sample_texel, 0);
  Float mu_s_d = atmClampCosine((r * mu_s + d * nu) / geometry.x);
  vec4 uvwz = vec4((nu + 1.0) / 2.0, scatteringUMuSFromMuS(atm_density, mu_s_d), geometry.y,
                   geometry.z);
  return lookupScatteringUvwz(atm_density, scattering_density_texture, uvwz) *
         texelFetch(ray_transmittance, sample_texel, 0);
}

// The first radius (z) of this dispatch: the pass runs a slice of radii at a time, so that a
// precompute can stop between slices (render/passes/precompute/atmosphere_gpu_precompute.cpp).
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
  ivec3 sample_texel = ivec3(0, texel.yz);
  Float dx = texelFetch(ray_geometry, sample_texel, 0).w;
  vec4 radiance = vec4(0.0);
  vec4 previous = integrand(sample_texel, r, mu_s, nu, 0.0);
  for (int i = 1; i <= ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES; ++i) {
    vec4 current = integrand(ivec3(i, texel.yz), r, mu_s, nu, Float(i) * dx);
    radiance += exponentialStepIntegral4(previous, current, dx);
    previous = current;
  }
  imageStore(delta_multiple_out, texel, radiance);
  imageStore(scattering_accumulated, texel,
             imageLoad(scattering_accumulated, texel) + radiance / rayleighPhaseFunction(nu));
}
