// GPU precomputation, step 4a (per order n >= 2): the scattering density J of order n from
// the radiance of order n-1 and the ground irradiance of order n-2.
//
// The quadrature of computeScatteringDensity (multiple_scattering.glsl, the CPU reference):
// 16 x 32 directions, midpoint rule, in the frame where the view direction is in the x-z
// plane, with the same table lookups. About 2.5x less work on llvmpipe (docs/atmosphere.md,
// "GPU precomputation") because the radiance of order n-1 comes from its nu slices
// (precompute_nu_slices.comp, the slices of this radius): one linearly filtered fetch per
// direction instead of two trilinear fetches (four at order 2); the ground's sun cosine is in
// closed form and its irradiance a 1D copy of the table's first row; the directions turn by a
// rotation instead of a cos and a sin each; phi and 2 pi - phi share their phase functions. No
// branch inside the loops (order 2 is a program of its own, the ground's directions a loop of
// their own): llvmpipe runs both sides of every branch.
#include "render/glsl/bindings.h"
#include "physics/atmosphere/multiple_scattering.glsl"
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;
uniform AtmosphereParameters atm;
// atm with the density table's sizes (GpuPrecomputeOptions::density_divisor; = atm by default):
// its texels' (r, mu, mu_s, nu); the other tables are read through atm.
uniform AtmosphereParameters atm_density;
layout(binding = SKYIG_UNIT_TRANSMITTANCE) uniform sampler2D transmittance_texture;
// The first row (the ground) of the irradiance of order n-2, as a 1D texture (GL_LINEAR).
layout(binding = SKYIG_UNIT_GROUND_IRRADIANCE) uniform sampler1D ground_irradiance_texture;
// precompute_nu_slices.comp: 1D array textures, GL_LINEAR along nu.
layout(binding = SKYIG_UNIT_NU_SLICES_A) uniform sampler1DArray slices_a;
layout(binding = SKYIG_UNIT_NU_SLICES_B) uniform sampler1DArray slices_b;
layout(binding = SKYIG_IMAGE_DELTA_DENSITY, rgba32f) uniform writeonly image3D density_out;

// The radiance of order n-1 arriving from a direction whose cosine with the sun is
// nu1_unclamped, from the nu slices: lookupScatteringUvwz's blend of two of them, with
// scatteringOfOrderUvwz's phase functions at order 1. Order 2 (from single scattering) is its
// own program (precompute_scattering_density_order2.comp defines
// SKYIG_DENSITY_FROM_SINGLE_SCATTERING): llvmpipe executes both sides of a branch under a
// mask, uniform or not, so a run-time test would make every order pay order 2's fetches.
vec4 skyRadiance(Float nu1_unclamped, Float layer, vec2 nu_to_coord) {
  Float nu1 = atmClampCosine(nu1_unclamped);
  // Between the slices floor(x) and floor(x) + 1, x = u_nu (nu_size - 1), as
  // lookupScatteringUvwz blends its two fetches: the texture coordinate (x + 0.5) / width,
  // linear in nu1 (one multiply-add; no division per direction).
  vec2 coord = vec2(nu1 * nu_to_coord.x + nu_to_coord.y, layer);
  vec4 radiance = texture(slices_a, coord);
#ifdef SKYIG_DENSITY_FROM_SINGLE_SCATTERING
  radiance = radiance * rayleighPhaseFunction(nu1) +
             texture(slices_b, coord) * miePhaseFunction(atm, nu1);
#endif
  return radiance;
}

// The ground's reflection seen in a direction that hits it at distance_to_ground. The ground
// point is at the radius bottom_radius, so the cosine of the sun's zenith angle there,
// dot(normalize(r zenith + d omega_i), omega_s), is (r mu_s + d nu1) / bottom_radius; the
// irradiance at the ground is the table's first row, looked up as lookupIrradiance does
// (GL_LINEAR along mu_s) in a 1D copy of that row.
vec4 groundRadiance(Float r, Float mu_s, Float nu1_unclamped, Float distance_to_ground,
                    vec4 ground_light) {
  Float mu_s_ground =
      atmClampCosine((r * mu_s + distance_to_ground * nu1_unclamped) / atm.bottom_radius);
  return ground_light *
         texture(ground_irradiance_texture,
                 textureCoordFromUnitRange(mu_s_ground * 0.5 + 0.5, atm.irradiance_width));
}

// The first radius (z) of this dispatch: the pass runs a slice of radii at a time, so that a
// precompute can stop between slices (render/passes/precompute/atmosphere_gpu_precompute.cpp).
uniform int z_offset;
void main() {
  ivec3 texel = ivec3(gl_GlobalInvocationID) + ivec3(0, 0, z_offset);
  if (any(greaterThanEqual(texel, imageSize(density_out)))) {
    return;
  }
  Float r;
  Float mu;
  Float mu_s;
  Float nu;
  bool ray_r_mu_intersects_ground;
  rMuMuSNuFromScatteringFragCoord(atm_density, vec3(texel) + vec3(0.5), r, mu, mu_s, nu,
                                  ray_r_mu_intersects_ground);
  int mu_s_size = int(atm.scattering_mu_s_size);
  int mu_s_index = texel.x - (texel.x / mu_s_size) * mu_s_size;

  // As computeScatteringDensity.
  vec3 omega = vec3(sqrt(max(1.0 - mu * mu, 0.0)), 0.0, mu);
  Float sun_dir_x = omega.x == 0.0 ? 0.0 : (nu - mu * mu_s) / omega.x;
  Float sun_dir_y = sqrt(max(1.0 - sun_dir_x * sun_dir_x - mu_s * mu_s, 0.0));
  vec3 omega_s = vec3(sun_dir_x, sun_dir_y, mu_s);
  const int SAMPLES = ATMOSPHERE_DENSITY_ANGULAR_SAMPLES;
  Float dphi = ATMOSPHERE_PI / Float(SAMPLES);
  Float dtheta = ATMOSPHERE_PI / Float(SAMPLES);
  Float altitude = r - atm.bottom_radius;
  vec4 rayleigh_coefficient = atm.rayleigh_scattering * rayleighDensity(atm, altitude);
  vec4 mie_coefficient = atm.mie_scattering * mieDensity(atm, altitude);
  // x = (nu1 + 1) / 2 (nu_size - 1) on slices nu_size + 1 texels wide.
  Float half_nu_scale = 0.5 * (atm.scattering_nu_size - 1.0);
  Float slice_width = atm.scattering_nu_size + 1.0;
  vec2 nu_to_coord = vec2(half_nu_scale, half_nu_scale + 0.5) / slice_width;
  // phi = (m + 1/2) dphi by rotation: cos and sin of dphi/2, then steps of dphi.
  Float cos_step = cos(dphi);
  Float sin_step = sin(dphi);
  Float cos_half = cos(0.5 * dphi);
  Float sin_half = sin(0.5 * dphi);
  // The incident radiance weighted by each phase function towards the view; the scattering
  // coefficients multiply the sums once, at the end.
  vec4 rayleigh_sum = vec4(0.0);
  vec4 mie_sum = vec4(0.0);

  // The directions that hit the ground are those of theta_l, l >= first_ground (cos theta
  // falls with l): two loops without a branch in them, since llvmpipe would run the ground's
  // reflection for every direction, the sky's too.
  int first_ground = SAMPLES;
  for (int l = SAMPLES - 1; l >= 0; --l) {
    if (rayIntersectsGround(atm, r, cos((Float(l) + 0.5) * dtheta))) first_ground = l;
  }
  for (int l = 0; l < first_ground; ++l) {
    Float theta = (Float(l) + 0.5) * dtheta;
    Float cos_theta = cos(theta);
    Float sin_theta = sin(theta);
    Float layer = Float(l * mu_s_size + mu_s_index);
    Float cos_phi = cos_half;
    Float sin_phi = sin_half;
    vec4 rayleigh_row = vec4(0.0);
    vec4 mie_row = vec4(0.0);
    // phi and 2 pi - phi (m and 2 SAMPLES - 1 - m) together: the view direction is in the
    // x-z plane, so both have the same phase functions towards it.
    for (int m = 0; m < SAMPLES; ++m) {
      Float x = cos_phi * sin_theta;
      Float y = sin_phi * sin_theta;
      Float next_cos = cos_phi * cos_step - sin_phi * sin_step;
      sin_phi = sin_phi * cos_step + cos_phi * sin_step;
      cos_phi = next_cos;
      Float nu1_plane = omega_s.x * x + omega_s.z * cos_theta;
      Float nu1_side = omega_s.y * y;
      vec4 incident_radiance = skyRadiance(nu1_plane + nu1_side, layer, nu_to_coord) +
                               skyRadiance(nu1_plane - nu1_side, layer, nu_to_coord);
      Float nu2 = omega.x * x + omega.z * cos_theta;
      rayleigh_row += incident_radiance * rayleighPhaseFunction(nu2);
      mie_row += incident_radiance * miePhaseFunction(atm, nu2);
    }
    Float domega_i = dtheta * dphi * sin_theta;
    rayleigh_sum += rayleigh_row * domega_i;
    mie_sum += mie_row * domega_i;
  }
  for (int l = first_ground; l < SAMPLES; ++l) {
    Float theta = (Float(l) + 0.5) * dtheta;
    Float cos_theta = cos(theta);
    Float sin_theta = sin(theta);
    Float distance_to_ground = distanceToBottomAtmosphereBoundary(atm, r, cos_theta);
    // The transmittance to the ground times albedo / pi.
    vec4 ground_light = transmittanceAlongRay(atm, transmittance_texture, r, cos_theta,
                                              distance_to_ground, true) *
                        atm.ground_albedo * (1.0 / ATMOSPHERE_PI);
    Float layer = Float(l * mu_s_size + mu_s_index);
    Float cos_phi = cos_half;
    Float sin_phi = sin_half;
    vec4 rayleigh_row = vec4(0.0);
    vec4 mie_row = vec4(0.0);
    for (int m = 0; m < SAMPLES; ++m) {
      Float x = cos_phi * sin_theta;
      Float y = sin_phi * sin_theta;
      Float next_cos = cos_phi * cos_step - sin_phi * sin_step;
      sin_phi = sin_phi * cos_step + cos_phi * sin_step;
      cos_phi = next_cos;
      Float nu1_plane = omega_s.x * x + omega_s.z * cos_theta;
      Float nu1_side = omega_s.y * y;
      Float nu1_a = nu1_plane + nu1_side;
      Float nu1_b = nu1_plane - nu1_side;
      vec4 incident_radiance =
          skyRadiance(nu1_a, layer, nu_to_coord) +
          groundRadiance(r, mu_s, nu1_a, distance_to_ground, ground_light) +
          skyRadiance(nu1_b, layer, nu_to_coord) +
          groundRadiance(r, mu_s, nu1_b, distance_to_ground, ground_light);
      Float nu2 = omega.x * x + omega.z * cos_theta;
      rayleigh_row += incident_radiance * rayleighPhaseFunction(nu2);
      mie_row += incident_radiance * miePhaseFunction(atm, nu2);
    }
    Float domega_i = dtheta * dphi * sin_theta;
    rayleigh_sum += rayleigh_row * domega_i;
    mie_sum += mie_row * domega_i;
  }
  vec4 rayleigh_mie = rayleigh_coefficient * rayleigh_sum + mie_coefficient * mie_sum;
  imageStore(density_out, texel, rayleigh_mie);
}
