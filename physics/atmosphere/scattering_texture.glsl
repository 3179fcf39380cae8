// The 4D parameterisation of the inscattered radiance S(r, mu, mu_s, nu) and its storage in a
// 3D table (Bruneton & Neyret 2008, section 4 "Parameterization" and section 6: 8 3D tables
// packed side by side along x, the 4th coordinate nu interpolated by hand).
//   u_r    = rho / H, rho = sqrt(r^2 - Rg^2), H = sqrt(Rt^2 - Rg^2)          (non-linear in r)
//   u_mu   = ratio of the distance to the ray's end (ground or top) to the distance to the
//            horizon (ground) or to the top through the horizon: in [0, 1/2) for rays that
//            hit the ground, [1/2, 1] for the others, discontinuous at the horizon
//   u_mu_s = non-linear in mu_s, denser near the horizon; u_nu = (1 + nu) / 2
// This is the paper's mapping with the exact ranges of Bruneton's 2017 implementation, so the
// first and last texels fall exactly on the horizon, the zenith and the nadir.
#ifndef SKYIG_ATMOSPHERE_SCATTERING_TEXTURE_GLSL
#define SKYIG_ATMOSPHERE_SCATTERING_TEXTURE_GLSL
#include "physics/atmosphere/geometry.glsl"

// u_mu_s: mu_s through the distance from the ground to the top towards the sun, relative to
// its value at mu_s_min; denser towards the horizon where the light changes fastest. The same
// at every r and mu.
Float scatteringUMuSFromMuS(IN(AtmosphereParameters) atm, Float mu_s) {
  Float H = sqrt(atm.top_radius * atm.top_radius - atm.bottom_radius * atm.bottom_radius);
  Float d = distanceToTopAtmosphereBoundary(atm, atm.bottom_radius, mu_s);
  Float d_min = atm.top_radius - atm.bottom_radius;
  Float d_max = H;
  Float a = (d - d_min) / (d_max - d_min);
  Float D = distanceToTopAtmosphereBoundary(atm, atm.bottom_radius, atm.mu_s_min);
  Float A = (D - d_min) / (d_max - d_min);
  return textureCoordFromUnitRange(max(1.0 - a / A, 0.0) / (1.0 + a), atm.scattering_mu_s_size);
}

vec4 scatteringUvwzFromRMuMuSNu(IN(AtmosphereParameters) atm, Float r, Float mu, Float mu_s,
                                Float nu, bool ray_r_mu_intersects_ground) {
  Float H = sqrt(atm.top_radius * atm.top_radius - atm.bottom_radius * atm.bottom_radius);
  Float rho = atmSafeSqrt(r * r - atm.bottom_radius * atm.bottom_radius);
  Float u_r = textureCoordFromUnitRange(rho / H, atm.scattering_r_size);

  Float r_mu = r * mu;
  Float discriminant = r_mu * r_mu - r * r + atm.bottom_radius * atm.bottom_radius;
  Float u_mu;
  if (ray_r_mu_intersects_ground) {
    // Distance to the ground, between r - Rg (straight down) and rho (the horizon).
    Float d = -r_mu - atmSafeSqrt(discriminant);
    Float d_min = r - atm.bottom_radius;
    Float d_max = rho;
    u_mu = 0.5 - 0.5 * textureCoordFromUnitRange(d_max == d_min ? 0.0 : (d - d_min) / (d_max - d_min),
                                                 atm.scattering_mu_size / 2.0);
  } else {
    // Distance to the top, between Rt - r (straight up) and rho + H (through the horizon).
    Float d = -r_mu + atmSafeSqrt(discriminant + H * H);
    Float d_min = atm.top_radius - r;
    Float d_max = rho + H;
    u_mu = 0.5 + 0.5 * textureCoordFromUnitRange((d - d_min) / (d_max - d_min),
                                                 atm.scattering_mu_size / 2.0);
  }

  Float u_nu = (nu + 1.0) / 2.0;
  return vec4(u_nu, scatteringUMuSFromMuS(atm, mu_s), u_mu, u_r);
}

void rMuMuSNuFromScatteringUvwz(IN(AtmosphereParameters) atm, IN(vec4) uvwz, OUT(Float) r,
                                OUT(Float) mu, OUT(Float) mu_s, OUT(Float) nu,
                                OUT(bool) ray_r_mu_intersects_ground) {
  Float H = sqrt(atm.top_radius * atm.top_radius - atm.bottom_radius * atm.bottom_radius);
  Float rho = H * unitRangeFromTextureCoord(uvwz.w, atm.scattering_r_size);
  r = sqrt(rho * rho + atm.bottom_radius * atm.bottom_radius);

  if (uvwz.z < 0.5) {
    Float d_min = r - atm.bottom_radius;
    Float d_max = rho;
    Float d = d_min + (d_max - d_min) * unitRangeFromTextureCoord(
                                            1.0 - 2.0 * uvwz.z, atm.scattering_mu_size / 2.0);
    mu = d == 0.0 ? -1.0 : atmClampCosine(-(rho * rho + d * d) / (2.0 * r * d));
    ray_r_mu_intersects_ground = true;
  } else {
    Float d_min = atm.top_radius - r;
    Float d_max = rho + H;
    Float d = d_min + (d_max - d_min) * unitRangeFromTextureCoord(
                                            2.0 * uvwz.z - 1.0, atm.scattering_mu_size / 2.0);
    mu = d == 0.0 ? 1.0 : atmClampCosine((H * H - rho * rho - d * d) / (2.0 * r * d));
    ray_r_mu_intersects_ground = false;
  }

  Float x_mu_s = unitRangeFromTextureCoord(uvwz.y, atm.scattering_mu_s_size);
  Float d_min = atm.top_radius - atm.bottom_radius;
  Float d_max = H;
  Float D = distanceToTopAtmosphereBoundary(atm, atm.bottom_radius, atm.mu_s_min);
  Float A = (D - d_min) / (d_max - d_min);
  Float a = (A - x_mu_s * A) / (1.0 + x_mu_s * A);
  Float d = d_min + min(a, A) * (d_max - d_min);
  mu_s = d == 0.0 ? 1.0
                  : atmClampCosine((H * H - d * d) / (2.0 * atm.bottom_radius * d));
  nu = atmClampCosine(uvwz.x * 2.0 - 1.0);
}

// Parameters of the texel whose centre is frag_coord (texels) in the 3D table of
// (nu_size * mu_s_size) x mu_size x r_size texels. nu is clamped to the values that the
// geometry allows for the given mu and mu_s.
void rMuMuSNuFromScatteringFragCoord(IN(AtmosphereParameters) atm, IN(vec3) frag_coord,
                                     OUT(Float) r, OUT(Float) mu, OUT(Float) mu_s,
                                     OUT(Float) nu, OUT(bool) ray_r_mu_intersects_ground) {
  Float frag_coord_nu = floor(frag_coord.x / atm.scattering_mu_s_size);
  Float frag_coord_mu_s = frag_coord.x - frag_coord_nu * atm.scattering_mu_s_size;
  vec4 uvwz = vec4(frag_coord_nu / (atm.scattering_nu_size - 1.0),
                   frag_coord_mu_s / atm.scattering_mu_s_size,
                   frag_coord.y / atm.scattering_mu_size, frag_coord.z / atm.scattering_r_size);
  rMuMuSNuFromScatteringUvwz(atm, uvwz, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  Float spread = sqrt(max((1.0 - mu * mu) * (1.0 - mu_s * mu_s), 0.0));
  nu = clamp(nu, mu * mu_s - spread, mu * mu_s + spread);
}

// Lookup of a 4D function stored as above, from table coordinates: two trilinear fetches,
// blended along nu. Callers that vary only nu compute uvwz once and change uvwz.x.
vec4 lookupScatteringUvwz(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_texture,
                          IN(vec4) uvwz) {
  Float tex_coord_x = uvwz.x * (atm.scattering_nu_size - 1.0);
  Float tex_x = floor(tex_coord_x);
  Float lerp = tex_coord_x - tex_x;
  vec3 uvw0 = vec3((tex_x + uvwz.y) / atm.scattering_nu_size, uvwz.z, uvwz.w);
  vec3 uvw1 = vec3((tex_x + 1.0 + uvwz.y) / atm.scattering_nu_size, uvwz.z, uvwz.w);
  return texture(scattering_texture, uvw0) * (1.0 - lerp) +
         texture(scattering_texture, uvw1) * lerp;
}

vec4 lookupScattering(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_texture, Float r,
                      Float mu, Float mu_s, Float nu, bool ray_r_mu_intersects_ground) {
  return lookupScatteringUvwz(
      atm, scattering_texture,
      scatteringUvwzFromRMuMuSNu(atm, r, mu, mu_s, nu, ray_r_mu_intersects_ground));
}

#endif
