// Single scattering S[L0] (Bruneton & Neyret 2008, eq. 7 with L = L0, the sun attenuated by
// T): the sunlight scattered once towards the viewer, integrated from x to the end of the ray.
// The phase functions are applied at lookup time (section 4 "Angular precision": the single
// Mie term is stored apart so its sharp forward peak is exact), so the tables hold
// S_R = beta_R^s int T rho_R and S_M = beta_M^s int T rho_M.
#ifndef SKYIG_ATMOSPHERE_SINGLE_SCATTERING_GLSL
#define SKYIG_ATMOSPHERE_SINGLE_SCATTERING_GLSL
#include "physics/atmosphere/transmittance.glsl"
#include "physics/atmosphere/scattering_texture.glsl"

// Integrand at distance d: transmittance viewer -> point and point -> sun, times density.
void singleScatteringIntegrand(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                               Float r, Float mu, Float mu_s, Float nu, Float d,
                               bool ray_r_mu_intersects_ground, OUT(vec4) rayleigh,
                               OUT(vec4) mie) {
  Float r_d = radiusAtDistance(atm, r, mu, d);
  Float mu_s_d = atmClampCosine((r * mu_s + d * nu) / r_d);
  vec4 transmittance =
      transmittanceAlongRay(atm, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground) *
      transmittanceToSun(atm, transmittance_texture, r_d, mu_s_d);
  rayleigh = transmittance * rayleighDensity(atm, r_d - atm.bottom_radius);
  mie = transmittance * mieDensity(atm, r_d - atm.bottom_radius);
}

// Integral over the ray up to the ground or the top of the atmosphere, step by step with
// the integrand taken as exponential between samples (exponentialStepIntegral4).
void computeSingleScattering(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                             Float r, Float mu, Float mu_s, Float nu,
                             bool ray_r_mu_intersects_ground, OUT(vec4) rayleigh,
                             OUT(vec4) mie) {
  Float dx = distanceToNearestAtmosphereBoundary(atm, r, mu, ray_r_mu_intersects_ground) /
             Float(ATMOSPHERE_SINGLE_SCATTERING_SAMPLES);
  vec4 rayleigh_sum = vec4(0.0);
  vec4 mie_sum = vec4(0.0);
  vec4 rayleigh_previous;
  vec4 mie_previous;
  singleScatteringIntegrand(atm, transmittance_texture, r, mu, mu_s, nu, 0.0,
                            ray_r_mu_intersects_ground, rayleigh_previous, mie_previous);
  for (int i = 1; i <= ATMOSPHERE_SINGLE_SCATTERING_SAMPLES; ++i) {
    Float d_i = Float(i) * dx;
    vec4 rayleigh_i;
    vec4 mie_i;
    singleScatteringIntegrand(atm, transmittance_texture, r, mu, mu_s, nu, d_i,
                              ray_r_mu_intersects_ground, rayleigh_i, mie_i);
    rayleigh_sum += exponentialStepIntegral4(rayleigh_previous, rayleigh_i, dx);
    mie_sum += exponentialStepIntegral4(mie_previous, mie_i, dx);
    rayleigh_previous = rayleigh_i;
    mie_previous = mie_i;
  }
  rayleigh = rayleigh_sum * atm.solar_irradiance * atm.rayleigh_scattering;
  mie = mie_sum * atm.solar_irradiance * atm.mie_scattering;
}

void computeSingleScatteringTexel(IN(AtmosphereParameters) atm,
                                  IN(sampler2D) transmittance_texture, IN(vec3) frag_coord,
                                  OUT(vec4) rayleigh, OUT(vec4) mie) {
  Float r;
  Float mu;
  Float mu_s;
  Float nu;
  bool ray_r_mu_intersects_ground;
  rMuMuSNuFromScatteringFragCoord(atm, frag_coord, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  computeSingleScattering(atm, transmittance_texture, r, mu, mu_s, nu,
                          ray_r_mu_intersects_ground, rayleigh, mie);
}

#endif
