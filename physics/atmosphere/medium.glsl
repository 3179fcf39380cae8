// Densities and phase functions of the two scattering constituents and of ozone.
#ifndef SKYIG_ATMOSPHERE_MEDIUM_GLSL
#define SKYIG_ATMOSPHERE_MEDIUM_GLSL
#include "physics/atmosphere/parameters.glsl"

// Relative densities (1 at the ground, or at the ozone peak) at an altitude in metres:
// exponential for molecules and aerosols (Bruneton & Neyret 2008, eq. 1 and 3), a tent for
// ozone (Bruneton 2017: 0 at 10 km, 1 at 25 km, 0 at 40 km by default).
Float rayleighDensity(IN(AtmosphereParameters) atm, Float altitude) {
  return clamp(exp(-altitude / atm.rayleigh_scale_height), 0.0, 1.0);
}

Float mieDensity(IN(AtmosphereParameters) atm, Float altitude) {
  return clamp(exp(-altitude / atm.mie_scale_height), 0.0, 1.0);
}

Float ozoneDensity(IN(AtmosphereParameters) atm, Float altitude) {
  return clamp(1.0 - abs(altitude - atm.ozone_center_altitude) / atm.ozone_half_width, 0.0, 1.0);
}

// Rayleigh phase function 3/(16 pi) (1 + nu^2), nu the cosine of the scattering angle
// (Bruneton & Neyret 2008, eq. 2).
Float rayleighPhaseFunction(Float nu) {
  return 3.0 / (16.0 * ATMOSPHERE_PI) * (1.0 + nu * nu);
}

// Cornette-Shanks phase function (Cornette & Shanks 1992; Bruneton & Neyret 2008, eq. 4):
// 3/(8 pi) (1 - g^2)(1 + nu^2) / ((2 + g^2)(1 + g^2 - 2 g nu)^(3/2)). Normalised to 1 over
// the sphere.
Float cornetteShanksPhaseFunction(Float g, Float nu) {
  Float k = 3.0 / (8.0 * ATMOSPHERE_PI) * (1.0 - g * g) / (2.0 + g * g);
  Float t = 1.0 + g * g - 2.0 * g * nu;  // t^1.5 as t sqrt(t): cheaper than pow
  return k * (1.0 + nu * nu) / (t * sqrt(t));
}

// A Mie phase function tabulated at u_i = i / (N - 1), theta = pi u^2, dense where a real
// aerosol's forward peak is (a degree from the sun OPAC's types give 2.4-8.5 times a
// Cornette-Shanks lobe of the same asymmetry), interpolated linearly in ln p and in u.
Float tabulatedPhaseFunction(IN(AtmosphereParameters) atm, Float nu) {
  Float u = sqrt(acos(clamp(nu, -1.0, 1.0)) / ATMOSPHERE_PI) * Float(ATMOSPHERE_MIE_PHASE_SAMPLES - 1);
  int i = min(int(u), ATMOSPHERE_MIE_PHASE_SAMPLES - 2);
  return exp(mix(atm.mie_phase_log_table[i], atm.mie_phase_log_table[i + 1], u - Float(i)));
}

Float miePhaseFunction(IN(AtmosphereParameters) atm, Float nu) {
  return atm.mie_phase_tabulated > 0.5 ? tabulatedPhaseFunction(atm, nu)
                                       : cornetteShanksPhaseFunction(atm.mie_phase_g, nu);
}

#endif
