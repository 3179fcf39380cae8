// GPU precomputation, step 1b (per group, after the transmittance): what the single and
// multiple scattering integrals need along each ray of the scattering table that does not
// depend on the sun. Their integrand at the sample i of a ray (r, mu) takes the transmittance
// from the ray's start and the point's radius and table coordinates u_mu, u_r; these are the
// same for the nu_size x mu_s_size texels of a row (r, mu) and for every order, so this pass
// computes them once per row and sample: texel (i, mu index, r index) holds
// transmittanceAlongRay in ray_transmittance_out and (r_d, u_mu, u_r, dx) in ray_geometry_out,
// u_mu and u_r those of the scattering density's table (atm_density). The passes then read
// them with texelFetch: the same values, instead of two to six bilinear lookups and a
// dozen square roots per sample and texel.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/scattering_texture.glsl"
#include "physics/atmosphere/transmittance.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
// atm with the density table's sizes (GpuPrecomputeOptions::density_divisor; = atm by default).
uniform AtmosphereParameters atm_density;
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
layout(binding = SKYIG_IMAGE_RAY_TRANSMITTANCE, rgba32f) uniform writeonly image3D ray_transmittance_out;
layout(binding = SKYIG_IMAGE_RAY_GEOMETRY, rgba32f) uniform writeonly image3D ray_geometry_out;
// The first radius (z) of this dispatch: the pass runs a slice of radii at a time, so that a
// precompute can stop between slices (render/passes/precompute/atmosphere_gpu_precompute.cpp).
uniform int z_offset;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, z_offset);
  if (any(greaterThanEqual(texel, imageSize(ray_transmittance_out)))) {
    return;
  }
  // r and mu as the scattering texels of this row compute them (they do not depend on x).
  Float r;
  Float mu;
  Float mu_s;
  Float nu;
  bool ray_r_mu_intersects_ground;
  rMuMuSNuFromScatteringFragCoord(atm, vec3(0.5, Float(texel.y) + 0.5, Float(texel.z) + 0.5), r,
                                  mu, mu_s, nu, ray_r_mu_intersects_ground);
  // ATMOSPHERE_SINGLE_SCATTERING_SAMPLES = ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES (checked by
  // the host), so both integrals sample the ray at the same points.
  Float dx = distanceToNearestAtmosphereBoundary(atm, r, mu, ray_r_mu_intersects_ground) /
             Float(ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES);
  Float d = Float(texel.x) * dx;
  Float r_d = radiusAtDistance(atm, r, mu, d);
  Float mu_d = atmClampCosine((r * mu + d) / r_d);
  vec4 uvwz = scatteringUvwzFromRMuMuSNu(atm_density, r_d, mu_d, 1.0, 0.0,
                                         ray_r_mu_intersects_ground);
  imageStore(ray_transmittance_out, texel,
             transmittanceAlongRay(atm, transmittance_texture, r, mu, d,
                                   ray_r_mu_intersects_ground));
  imageStore(ray_geometry_out, texel, vec4(r_d, uvwz.z, uvwz.w, dx));
}
