// GPU precomputation, step 3: single Rayleigh and Mie scattering into the delta tables, and
// the accumulated tables initialised with them (C* = S_R[L0], C_M = S_M[L0]). The integral is
// computeSingleScattering's (single_scattering.glsl, the CPU reference), with the transmittance
// along the ray and the sample points' radii from precompute_ray_transmittance.comp: only the
// transmittance to the sun depends on mu_s and nu.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/single_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
// Per sample i of the ray of row (mu, r), texel (i, mu, r): the transmittance from the ray's
// start, and (r_d, u_mu, u_r, dx).
layout(binding = SKYIG_UNIT_RAY_TRANSMITTANCE) uniform sampler3D ray_transmittance;
layout(binding = SKYIG_UNIT_RAY_GEOMETRY) uniform sampler3D ray_geometry;
layout(binding = SKYIG_IMAGE_DELTA_RAYLEIGH, rgba32f) uniform writeonly image3D delta_rayleigh_out;
layout(binding = SKYIG_IMAGE_DELTA_MIE, rgba32f) uniform writeonly image3D delta_mie_out;
layout(binding = SKYIG_IMAGE_SCATTERING, rgba32f) uniform writeonly image3D scattering_out;
layout(binding = SKYIG_IMAGE_SINGLE_MIE, rgba32f) uniform writeonly image3D single_mie_out;

// singleScatteringIntegrand at the sample `sample_texel` (i, mu, r) of the ray.
void integrand(ivec3 sample_texel, Float r, Float mu_s, Float nu, Float d, OUT(vec4) rayleigh,
               OUT(vec4) mie) {
  Float r_d = texelFetch(ray_geometry, sample_texel, 0).x;
  Float mu_s_d = atmClampCosine((r * mu_s + d * nu) / r_d);
  vec4 transmittance = texelFetch(ray_transmittance, sample_texel, 0) *
                       transmittanceToSun(atm, transmittance_texture, r_d, mu_s_d);
  rayleigh = transmittance * rayleighDensity(atm, r_d - atm.bottom_radius);
  mie = transmittance * mieDensity(atm, r_d - atm.bottom_radius);
}

// The first radius (z) of this dispatch: the pass runs a slice of radii at a time, so that a
// precompute can stop between slices (render/passes/precompute/atmosphere_gpu_precompute.cpp).
uniform int z_offset;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, z_offset);
  if (any(greaterThanEqual(texel, imageSize(delta_rayleigh_out)))) {
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
  vec4 rayleigh_sum = vec4(0.0);
  vec4 mie_sum = vec4(0.0);
  vec4 rayleigh_previous;
  vec4 mie_previous;
  integrand(sample_texel, r, mu_s, nu, 0.0, rayleigh_previous, mie_previous);
  for (int i = 1; i <= ATMOSPHERE_SINGLE_SCATTERING_SAMPLES; ++i) {
    vec4 rayleigh_i;
    vec4 mie_i;
    integrand(ivec3(i, texel.yz), r, mu_s, nu, Float(i) * dx, rayleigh_i, mie_i);
    rayleigh_sum += exponentialStepIntegral4(rayleigh_previous, rayleigh_i, dx);
    mie_sum += exponentialStepIntegral4(mie_previous, mie_i, dx);
    rayleigh_previous = rayleigh_i;
    mie_previous = mie_i;
  }
  vec4 rayleigh = rayleigh_sum * atm.solar_irradiance * atm.rayleigh_scattering;
  vec4 mie = mie_sum * atm.solar_irradiance * atm.mie_scattering;
  imageStore(delta_rayleigh_out, texel, rayleigh);
  imageStore(delta_mie_out, texel, mie);
  imageStore(scattering_out, texel, rayleigh);
  imageStore(single_mie_out, texel, mie);
}
