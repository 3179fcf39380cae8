// Multiple scattering, one order after another (Bruneton & Neyret 2008, section 4, algorithm
// 4.1): from the radiance of order n-1 (delta S) and the ground irradiance of order n-2
// (delta E), the scattering density J of order n (eq. 7, the light scattered at a point
// towards a direction), then the radiance of order n (eq. 7, J integrated along the ray with
// T) and the ground irradiance of order n-1 (section 3, E-bar). The ground is a sphere of constant
// albedo here (section 3, "Notations": L-bar).
#ifndef SKYIG_ATMOSPHERE_MULTIPLE_SCATTERING_GLSL
#define SKYIG_ATMOSPHERE_MULTIPLE_SCATTERING_GLSL
#include "physics/atmosphere/single_scattering.glsl"
#include "physics/atmosphere/irradiance.glsl"

// Radiance of exactly `scattering_order` scatterings arriving from the direction whose table
// coordinates are uvwz (cosine of the scattering angle nu): the single scattering tables with
// their phase functions for order 1, the delta table otherwise.
vec4 scatteringOfOrderUvwz(IN(AtmosphereParameters) atm, IN(sampler3D) single_rayleigh_texture,
                           IN(sampler3D) single_mie_texture, IN(sampler3D) multiple_texture,
                           IN(vec4) uvwz, Float nu, int scattering_order) {
  if (scattering_order == 1) {
    vec4 rayleigh = lookupScatteringUvwz(atm, single_rayleigh_texture, uvwz);
    vec4 mie = lookupScatteringUvwz(atm, single_mie_texture, uvwz);
    return rayleigh * rayleighPhaseFunction(nu) + mie * miePhaseFunction(atm, nu);
  }
  return lookupScatteringUvwz(atm, multiple_texture, uvwz);
}

vec4 scatteringOfOrder(IN(AtmosphereParameters) atm, IN(sampler3D) single_rayleigh_texture,
                       IN(sampler3D) single_mie_texture, IN(sampler3D) multiple_texture, Float r,
                       Float mu, Float mu_s, Float nu, bool ray_r_mu_intersects_ground,
                       int scattering_order) {
  return scatteringOfOrderUvwz(
      atm, single_rayleigh_texture, single_mie_texture, multiple_texture,
      scatteringUvwzFromRMuMuSNu(atm, r, mu, mu_s, nu, ray_r_mu_intersects_ground), nu,
      scattering_order);
}

// Scattering density J of order n at (r, mu, mu_s, nu): the incident radiance of order n-1
// over the sphere of directions (plus, for directions that hit the ground, the ground's
// reflection of the irradiance of order n-2, attenuated to the point), times the scattering
// coefficients and phase functions towards -v. Midpoint rule in (theta, phi).
vec4 computeScatteringDensity(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                              IN(sampler3D) single_rayleigh_texture,
                              IN(sampler3D) single_mie_texture, IN(sampler3D) multiple_texture,
                              IN(sampler2D) irradiance_texture, Float r, Float mu, Float mu_s,
                              Float nu, int scattering_order) {
  // Local frame: zenith along z, view direction omega in the x-z plane.
  vec3 zenith_direction = vec3(0.0, 0.0, 1.0);
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
  vec4 rayleigh_mie = vec4(0.0);

  for (int l = 0; l < SAMPLES; ++l) {
    Float theta = (Float(l) + 0.5) * dtheta;
    Float cos_theta = cos(theta);
    Float sin_theta = sin(theta);
    bool ray_r_theta_intersects_ground = rayIntersectsGround(atm, r, cos_theta);

    // Ground reached in direction theta, and the light it reflects (Lambertian, albedo/pi).
    Float distance_to_ground = 0.0;
    vec4 transmittance_to_ground = vec4(0.0);
    vec4 ground_albedo = vec4(0.0);
    if (ray_r_theta_intersects_ground) {
      distance_to_ground = distanceToBottomAtmosphereBoundary(atm, r, cos_theta);
      transmittance_to_ground = transmittanceAlongRay(atm, transmittance_texture, r, cos_theta,
                                                      distance_to_ground, true);
      ground_albedo = atm.ground_albedo;
    }

    // Only nu changes with phi: the other three table coordinates are computed once.
    vec4 uvwz = scatteringUvwzFromRMuMuSNu(atm, r, cos_theta, mu_s, 0.0,
                                           ray_r_theta_intersects_ground);
    for (int m = 0; m < 2 * SAMPLES; ++m) {
      Float phi = (Float(m) + 0.5) * dphi;
      vec3 omega_i = vec3(cos(phi) * sin_theta, sin(phi) * sin_theta, cos_theta);
      Float domega_i = dtheta * dphi * sin_theta;

      Float nu1 = atmClampCosine(dot(omega_s, omega_i));
      vec4 incident_radiance = scatteringOfOrderUvwz(
          atm, single_rayleigh_texture, single_mie_texture, multiple_texture,
          vec4((nu1 + 1.0) / 2.0, uvwz.y, uvwz.z, uvwz.w), nu1, scattering_order - 1);
      if (ray_r_theta_intersects_ground) {
        vec3 ground_normal = normalize(zenith_direction * r + omega_i * distance_to_ground);
        vec4 ground_irradiance = lookupIrradiance(atm, irradiance_texture, atm.bottom_radius,
                                                  dot(ground_normal, omega_s));
        incident_radiance +=
            transmittance_to_ground * ground_albedo * (1.0 / ATMOSPHERE_PI) * ground_irradiance;
      }

      // Scattered from omega_i towards -omega: the phase functions take the angle between
      // the propagation directions, whose cosine is dot(omega, omega_i).
      Float nu2 = dot(omega, omega_i);
      rayleigh_mie += incident_radiance *
                      (rayleigh_coefficient * rayleighPhaseFunction(nu2) +
                       mie_coefficient * miePhaseFunction(atm, nu2)) *
                      domega_i;
    }
  }
  return rayleigh_mie;
}

vec4 computeScatteringDensityTexel(IN(AtmosphereParameters) atm,
                                   IN(sampler2D) transmittance_texture,
                                   IN(sampler3D) single_rayleigh_texture,
                                   IN(sampler3D) single_mie_texture,
                                   IN(sampler3D) multiple_texture,
                                   IN(sampler2D) irradiance_texture, IN(vec3) frag_coord,
                                   int scattering_order) {
  Float r;
  Float mu;
  Float mu_s;
  Float nu;
  bool ray_r_mu_intersects_ground;
  rMuMuSNuFromScatteringFragCoord(atm, frag_coord, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  return computeScatteringDensity(atm, transmittance_texture, single_rayleigh_texture,
                                  single_mie_texture, multiple_texture, irradiance_texture, r,
                                  mu, mu_s, nu, scattering_order);
}

// Radiance of order n: J of order n integrated along the ray with the transmittance to the
// viewer, the integrand taken as exponential between samples (exponentialStepIntegral4).
vec4 multipleScatteringIntegrand(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                                 IN(sampler3D) scattering_density_texture, Float r, Float mu,
                                 Float mu_s, Float nu, Float d, bool ray_r_mu_intersects_ground) {
  Float r_d = radiusAtDistance(atm, r, mu, d);
  Float mu_d = atmClampCosine((r * mu + d) / r_d);
  Float mu_s_d = atmClampCosine((r * mu_s + d * nu) / r_d);
  return lookupScattering(atm, scattering_density_texture, r_d, mu_d, mu_s_d, nu,
                          ray_r_mu_intersects_ground) *
         transmittanceAlongRay(atm, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground);
}

vec4 computeMultipleScattering(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                               IN(sampler3D) scattering_density_texture, Float r, Float mu,
                               Float mu_s, Float nu, bool ray_r_mu_intersects_ground) {
  Float dx = distanceToNearestAtmosphereBoundary(atm, r, mu, ray_r_mu_intersects_ground) /
             Float(ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES);
  vec4 sum = vec4(0.0);
  vec4 previous = multipleScatteringIntegrand(atm, transmittance_texture,
                                              scattering_density_texture, r, mu, mu_s, nu, 0.0,
                                              ray_r_mu_intersects_ground);
  for (int i = 1; i <= ATMOSPHERE_MULTIPLE_SCATTERING_SAMPLES; ++i) {
    vec4 current = multipleScatteringIntegrand(atm, transmittance_texture,
                                               scattering_density_texture, r, mu, mu_s, nu,
                                               Float(i) * dx, ray_r_mu_intersects_ground);
    sum += exponentialStepIntegral4(previous, current, dx);
    previous = current;
  }
  return sum;
}

// Returns the radiance of order n at the texel, and its nu (the accumulated table stores it
// divided by the Rayleigh phase function, as the single Rayleigh term: section 4, C*).
vec4 computeMultipleScatteringTexel(IN(AtmosphereParameters) atm,
                                    IN(sampler2D) transmittance_texture,
                                    IN(sampler3D) scattering_density_texture,
                                    IN(vec3) frag_coord, OUT(Float) nu) {
  Float r;
  Float mu;
  Float mu_s;
  bool ray_r_mu_intersects_ground;
  rMuMuSNuFromScatteringFragCoord(atm, frag_coord, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  return computeMultipleScattering(atm, transmittance_texture, scattering_density_texture, r, mu,
                                   mu_s, nu, ray_r_mu_intersects_ground);
}

// Irradiance of order n on a horizontal surface from the radiance of order n (section 3, E-bar, with
// the ground's cosine factor), integrated over the upper hemisphere.
vec4 computeIndirectIrradiance(IN(AtmosphereParameters) atm,
                               IN(sampler3D) single_rayleigh_texture,
                               IN(sampler3D) single_mie_texture, IN(sampler3D) multiple_texture,
                               Float r, Float mu_s, int scattering_order) {
  const int SAMPLES = ATMOSPHERE_IRRADIANCE_ANGULAR_SAMPLES;
  Float dphi = ATMOSPHERE_PI / Float(SAMPLES);
  Float dtheta = ATMOSPHERE_PI / Float(SAMPLES);
  vec4 result = vec4(0.0);
  vec3 omega_s = vec3(sqrt(max(1.0 - mu_s * mu_s, 0.0)), 0.0, mu_s);
  for (int j = 0; j < SAMPLES / 2; ++j) {
    Float theta = (Float(j) + 0.5) * dtheta;
    vec4 uvwz = scatteringUvwzFromRMuMuSNu(atm, r, cos(theta), mu_s, 0.0, false);
    for (int i = 0; i < 2 * SAMPLES; ++i) {
      Float phi = (Float(i) + 0.5) * dphi;
      vec3 omega = vec3(cos(phi) * sin(theta), sin(phi) * sin(theta), cos(theta));
      Float domega = dtheta * dphi * sin(theta);
      Float nu = atmClampCosine(dot(omega, omega_s));
      result += scatteringOfOrderUvwz(atm, single_rayleigh_texture, single_mie_texture,
                                      multiple_texture, vec4((nu + 1.0) / 2.0, uvwz.y, uvwz.z, uvwz.w),
                                      nu, scattering_order) *
                omega.z * domega;
    }
  }
  return result;
}

vec4 computeIndirectIrradianceTexel(IN(AtmosphereParameters) atm,
                                    IN(sampler3D) single_rayleigh_texture,
                                    IN(sampler3D) single_mie_texture,
                                    IN(sampler3D) multiple_texture, IN(vec2) frag_coord,
                                    int scattering_order) {
  Float r;
  Float mu_s;
  rMuSFromIrradianceFragCoord(atm, frag_coord, r, mu_s);
  return computeIndirectIrradiance(atm, single_rayleigh_texture, single_mie_texture,
                                   multiple_texture, r, mu_s, scattering_order);
}

#endif
