// GPU precomputation, step 4a' (per order n >= 2, before the scattering density): the radiance
// of order n-1 at the directions of the density's quadrature, as "nu slices".
//
// The scattering density (precompute_scattering_density.comp, the same quadrature as
// computeScatteringDensity in multiple_scattering.glsl) integrates over circles of directions
// of fixed theta, along which only nu changes. lookupScatteringUvwz blends two trilinear
// fetches at x = (k + u_mu_s) / nu_size, k = floor(u_nu (nu_size - 1)), at the circle's
// (u_mu_s, u_mu, u_r); these depend on (r, theta, mu_s) and k only. This pass makes those
// fetches once, for k = 0..nu_size: texel k of layer theta_index * mu_s_size + mu_s_index, for
// the radius the density computes next. The density then reads them with one GL_LINEAR fetch
// per direction, the blend lookupScatteringUvwz makes: same values, a fraction of the work.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform AtmosphereParameters atm;
// atm with the density table's sizes (GpuPrecomputeOptions::density_divisor; = atm by default).
uniform AtmosphereParameters atm_density;
uniform int scattering_order;  // n: the slices are of the radiance of order n - 1
layout(binding = SKYIG_UNIT_DELTA_RAYLEIGH) uniform sampler3D single_rayleigh_texture;
layout(binding = SKYIG_UNIT_DELTA_MIE) uniform sampler3D single_mie_texture;
layout(binding = SKYIG_UNIT_DELTA_MULTIPLE) uniform sampler3D multiple_texture;
// 1D array textures: the nu_size + 1 slices along x, one layer per (theta, mu_s), of the
// radius z_offset (the host runs the density of that radius next).
layout(binding = SKYIG_IMAGE_NU_SLICES_A, rgba32f) uniform writeonly image1DArray slices_a_out;  // Rayleigh or delta S
layout(binding = SKYIG_IMAGE_NU_SLICES_B, rgba32f) uniform writeonly image1DArray slices_b_out;  // Mie (order 1)
// The first radius (z) of this dispatch: the pass runs a slice of radii at a time, so that a
// precompute can stop between slices (render/passes/precompute/atmosphere_gpu_precompute.cpp).
uniform int z_offset;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, z_offset);
  int mu_s_size = int(atm.scattering_mu_s_size);
  int rows = ATMOSPHERE_DENSITY_ANGULAR_SAMPLES * mu_s_size;
  if (texel.x > int(atm.scattering_nu_size) || texel.y >= rows ||
      texel.z >= int(atm_density.scattering_r_size)) {
    return;
  }
  ivec2 slice = ivec2(texel.x, texel.y);  // one radius at a time (z_offset)
  int theta_index = texel.y / mu_s_size;
  int mu_s_index = texel.y - theta_index * mu_s_size;
  // r and mu_s exactly as the density's texels of this column and radius compute them.
  // (The density table may have fewer radii than the others: atm_density.)
  Float r;
  Float mu;
  Float mu_s;
  Float nu;
  bool ray_r_mu_intersects_ground;
  rMuMuSNuFromScatteringFragCoord(atm_density, vec3(Float(mu_s_index) + 0.5, 0.5, Float(texel.z) + 0.5),
                                  r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  Float dtheta = ATMOSPHERE_PI / Float(ATMOSPHERE_DENSITY_ANGULAR_SAMPLES);
  Float cos_theta = cos((Float(theta_index) + 0.5) * dtheta);
  vec4 uvwz = scatteringUvwzFromRMuMuSNu(atm, r, cos_theta, mu_s, 0.0,
                                         rayIntersectsGround(atm, r, cos_theta));
  vec3 uvw = vec3((Float(texel.x) + uvwz.y) / atm.scattering_nu_size, uvwz.z, uvwz.w);
  if (scattering_order - 1 == 1) {
    imageStore(slices_a_out, slice, texture(single_rayleigh_texture, uvw));
    imageStore(slices_b_out, slice, texture(single_mie_texture, uvw));
  } else {
    imageStore(slices_a_out, slice, texture(multiple_texture, uvw));
  }
}
