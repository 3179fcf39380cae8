// Irradiance on a horizontal ground element E(r, mu_s) (Bruneton & Neyret 2008, section 3 "Multiple scattering": the
// table E[L+] of the indirect light; the direct sun is evaluated at render time). The table
// is linear in mu_s and in r.
#ifndef SKYIG_ATMOSPHERE_IRRADIANCE_GLSL
#define SKYIG_ATMOSPHERE_IRRADIANCE_GLSL
#include "physics/atmosphere/transmittance.glsl"

vec2 irradianceUvFromRMuS(IN(AtmosphereParameters) atm, Float r, Float mu_s) {
  Float x_r = (r - atm.bottom_radius) / (atm.top_radius - atm.bottom_radius);
  Float x_mu_s = mu_s * 0.5 + 0.5;
  return vec2(textureCoordFromUnitRange(x_mu_s, atm.irradiance_width),
              textureCoordFromUnitRange(x_r, atm.irradiance_height));
}

void rMuSFromIrradianceFragCoord(IN(AtmosphereParameters) atm, IN(vec2) frag_coord,
                                 OUT(Float) r, OUT(Float) mu_s) {
  Float x_mu_s = unitRangeFromTextureCoord(frag_coord.x / atm.irradiance_width,
                                           atm.irradiance_width);
  Float x_r = unitRangeFromTextureCoord(frag_coord.y / atm.irradiance_height,
                                        atm.irradiance_height);
  r = atm.bottom_radius + x_r * (atm.top_radius - atm.bottom_radius);
  mu_s = atmClampCosine(2.0 * x_mu_s - 1.0);
}

vec4 lookupIrradiance(IN(AtmosphereParameters) atm, IN(sampler2D) irradiance_texture, Float r,
                      Float mu_s) {
  return texture(irradiance_texture, irradianceUvFromRMuS(atm, r, mu_s));
}

// Direct sun on a horizontal surface: the cosine factor averaged over the visible part of
// the sun disc (Bruneton 2017), times the transmittance.
vec4 computeDirectIrradiance(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                             Float r, Float mu_s) {
  Float alpha_s = atm.sun_angular_radius;
  Float average_cosine_factor =
      mu_s < -alpha_s ? 0.0
                      : (mu_s > alpha_s ? mu_s : (mu_s + alpha_s) * (mu_s + alpha_s) / (4.0 * alpha_s));
  return atm.solar_irradiance *
         transmittanceToTopAtmosphereBoundary(atm, transmittance_texture, r, mu_s) *
         average_cosine_factor;
}

vec4 computeDirectIrradianceTexel(IN(AtmosphereParameters) atm,
                                  IN(sampler2D) transmittance_texture, IN(vec2) frag_coord) {
  Float r;
  Float mu_s;
  rMuSFromIrradianceFragCoord(atm, frag_coord, r, mu_s);
  return computeDirectIrradiance(atm, transmittance_texture, r, mu_s);
}

#endif
