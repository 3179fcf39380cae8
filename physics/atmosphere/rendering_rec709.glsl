// Sky radiance from tables already converted to linear Rec.709 (cd/m^2 per unit phase
// function): the sum over all wavelength groups of each group's C* and C_M times the 3 x 4
// block of the spectral-to-Rec.709 matrix (physics/atmosphere/precompute/rec709_tables.h). Exact for the
// sky, because both phase functions are the same at every wavelength (paper eq. 2 and 4 with
// a grey g), so phase and colour conversion commute; one table pair for any number of
// wavelengths, which is what keeps the GPU tables within budget.
#ifndef SKYIG_ATMOSPHERE_RENDERING_REC709_GLSL
#define SKYIG_ATMOSPHERE_RENDERING_REC709_GLSL
#include "physics/atmosphere/rendering.glsl"

// Linear Rec.709 (Y in cd/m^2) of the light scattered into the view ray; atm supplies the
// geometry and table sizes (the same for every group).
vec3 skyRec709(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_rec709,
               IN(sampler3D) single_mie_rec709, IN(vec3) camera_position, IN(vec3) view_ray,
               IN(vec3) sun_direction) {
  vec3 camera = camera_position;
  Float r;
  Float rmu;
  if (!enterAtmosphere(atm, camera, view_ray, r, rmu)) {
    return vec3(0.0);
  }
  Float mu = atmClampCosine(rmu / r);
  Float mu_s = atmClampCosine(dot(camera, sun_direction) / r);
  Float nu = atmClampCosine(dot(view_ray, sun_direction));
  vec4 rgb = scatteredRadiance(atm, scattering_rec709, single_mie_rec709, r, mu, mu_s, nu,
                               rayIntersectsGround(atm, r, mu));
  return vec3(rgb.x, rgb.y, rgb.z);
}

// ---- The renderer's packed tables (physics/atmosphere/precompute/rec709_tables.h, PackedRec709Tables) ----
// scattering_packed: C*.rgb and C_M.b (alpha); single_mie_rg: C_M.rg; both in Rec.709 times
// REC709_TABLE_SCALE (half floats). transmittance_xyz: the optical depth tau_c = -ln T_c of the
// sun-weighted CIE XYZ transmittance T_c = sum_i w_c(i) E_sun(i) T(i) / sum_i w_c(i) E_sun(i)
// (w >= 0, so 0 <= T_c <= 1; alpha: a depth of 0), read like the spectral table;
// irradiance_xyz: the sky irradiance table in XYZ (lux; exact, it is linear).
// Light that crosses the air (aerial perspective, ground, sun disc) is attenuated per XYZ
// channel: exact for the sun disc and the direct sunlight (the spectrum the weights assume),
// an approximation for anything else (documented and bounded in docs/atmosphere.md).
#define REC709_TABLE_SCALE 0.0625

// IEC 61966-2-1 (the same matrix as physics/spectrum/spectrum.cpp).
vec3 xyzToRec709Linear(IN(vec3) c) {
  return vec3(3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
              -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
              0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z);
}

// Rec.709 radiance scattered towards the viewer at table coordinates uvwz (both tables share
// them, so they are computed once).
vec3 packedScatteredRec709(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_packed,
                           IN(sampler3D) single_mie_rg, IN(vec4) uvwz, Float nu) {
  vec4 s = lookupScatteringUvwz(atm, scattering_packed, uvwz);
  vec4 m = lookupScatteringUvwz(atm, single_mie_rg, uvwz);
  vec3 rayleigh = vec3(s.x, s.y, s.z);
  vec3 mie = vec3(m.x, m.y, s.w);
  return (rayleigh * rayleighPhaseFunction(nu) + mie * miePhaseFunction(atm, nu)) *
         (1.0 / REC709_TABLE_SCALE);
}

// Sky radiance (Rec.709, cd/m^2) along view_ray lit from light_direction, from the packed
// tables, for a camera already inside the atmosphere at radius r (rmu = dot(camera, view)).
vec3 packedSkyInsideRec709(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_packed,
                           IN(sampler3D) single_mie_rg, IN(vec3) camera, Float r, Float rmu,
                           IN(vec3) view_ray, IN(vec3) light_direction) {
  Float mu = atmClampCosine(rmu / r);
  Float mu_s = atmClampCosine(dot(camera, light_direction) / r);
  Float nu = atmClampCosine(dot(view_ray, light_direction));
  vec4 uvwz = scatteringUvwzFromRMuMuSNu(atm, r, mu, mu_s, nu, rayIntersectsGround(atm, r, mu));
  return packedScatteredRec709(atm, scattering_packed, single_mie_rg, uvwz, nu);
}

// The same from anywhere (the camera may be in space): skyRadiance() without transmittance.
vec3 packedSkyRec709(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_packed,
                     IN(sampler3D) single_mie_rg, IN(vec3) camera_position, IN(vec3) view_ray,
                     IN(vec3) light_direction) {
  vec3 camera = camera_position;
  Float r;
  Float rmu;
  if (!enterAtmosphere(atm, camera, view_ray, r, rmu)) {
    return vec3(0.0);
  }
  return packedSkyInsideRec709(atm, scattering_packed, single_mie_rg, camera, r, rmu, view_ray,
                               light_direction);
}

// Where a view falls on the sun's disc: sin(angle from the centre) / sin(radius), below 1 on
// the disc, from the chord |view - sun| = 2 sin(angle / 2) rather than from 1 - cos^2. In single
// precision the cosine of a quarter degree, 1 - 1e-5, is known to 6e-8 only: the limb would be
// ragged by 0.02 deg (a pixel and a half of a 40-pixel disc) and the limb darkening noisy.
Float sunDiscFraction(IN(vec3) disc_ray, IN(vec3) sun_direction, Float sin_radius) {
  if (dot(disc_ray, sun_direction) <= 0.0) return 2.0;
  vec3 d = disc_ray - sun_direction;
  Float chord2 = dot(d, d);
  return sqrt(max(chord2 * (1.0 - 0.25 * chord2), 0.0)) / sin_radius;
}

// The limb-darkened, attenuated sun disc in XYZ (cd/m^2 for Y) at x (sunDiscFraction, below 1),
// its light reaching the camera along view_ray; the limb darkening exponent per XYZ channel
// (sun-weighted mean of the spectral exponents). physical_sky.frag takes x at the middle of the
// part of a pixel on the disc (its limb anti-aliased).
vec3 packedSunDiscAtXyz(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_xyz,
                        IN(vec3) solar_irradiance_xyz, IN(vec3) limb_darkening_xyz,
                        IN(vec3) camera_position, IN(vec3) view_ray, Float x) {
  Float r = length(camera_position);
  Float mu_view = dot(camera_position, view_ray) / r;
  Float rmu = r * mu_view;
  Float discriminant_ground = rmu * rmu - r * r + atm.bottom_radius * atm.bottom_radius;
  if (rmu < 0.0 && discriminant_ground >= 0.0) {
    return vec3(0.0);  // behind the planet
  }
  vec4 t = vec4(1.0);
  if (r <= atm.top_radius) {
    t = transmittanceToTopAtmosphereBoundary(atm, transmittance_xyz, r, mu_view);
  } else {
    Float discriminant_top = rmu * rmu - r * r + atm.top_radius * atm.top_radius;
    if (rmu < 0.0 && discriminant_top >= 0.0) {
      vec3 entry = camera_position + view_ray * (-rmu - sqrt(discriminant_top));
      t = transmittanceToTopAtmosphereBoundary(atm, transmittance_xyz, atm.top_radius,
                                               dot(entry, view_ray) / atm.top_radius);
    }
  }
  Float mu = sqrt(max(1.0 - x * x, 0.0));
  vec3 a = limb_darkening_xyz;
  vec3 darkening = vec3(pow(mu, a.x), pow(mu, a.y), pow(mu, a.z)) * (a + vec3(2.0)) * 0.5;
  return solar_irradiance_xyz / (ATMOSPHERE_PI * atm.sun_angular_radius * atm.sun_angular_radius) *
         darkening * vec3(t.x, t.y, t.z);
}

// The disc where disc_ray, the airless direction the pixel sees (physics/common/refraction.glsl:
// unrefractView), falls within the sun's radius; its light reaches the camera along view_ray,
// the apparent direction, and is attenuated by that ray's own transmittance: the lower limb of a
// setting sun redder and dimmer than the upper, smoothly, as the transmittance table is.
vec3 packedRefractedSunDiscXyz(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_xyz,
                               IN(vec3) solar_irradiance_xyz, IN(vec3) limb_darkening_xyz,
                               IN(vec3) camera_position, IN(vec3) view_ray, IN(vec3) disc_ray,
                               IN(vec3) sun_direction) {
  Float x = sunDiscFraction(disc_ray, sun_direction, sin(atm.sun_angular_radius));
  if (x >= 1.0) {
    return vec3(0.0);
  }
  return packedSunDiscAtXyz(atm, transmittance_xyz, solar_irradiance_xyz, limb_darkening_xyz, camera_position,
                            view_ray, x);
}

// The same without refraction (a camera in space sees the sun along its own direction).
vec3 packedSunDiscXyz(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_xyz,
                      IN(vec3) solar_irradiance_xyz, IN(vec3) limb_darkening_xyz,
                      IN(vec3) camera_position, IN(vec3) view_ray, IN(vec3) sun_direction) {
  return packedRefractedSunDiscXyz(atm, transmittance_xyz, solar_irradiance_xyz, limb_darkening_xyz,
                                   camera_position, view_ray, view_ray, sun_direction);
}

// The Lambertian ground at distance d along view_ray (camera inside the atmosphere, the ray
// hits the ground), lit by the direct light and the sky from light_direction (XYZ, the sky
// table holds a horizontal surface, the ground's normal is its radius), attenuated by the
// sun-weighted XYZ transmittance of the segment. Returns Rec.709. The light scattered into
// the segment is packedSkyRec709 of the same ray (the table's ground-hitting rays end there,
// paper section 4). For the moon (Jensen et al. 2001) the same, times its Rec.709 scale.
vec3 packedGroundReflectionRec709(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_xyz,
                                  IN(sampler2D) irradiance_xyz, IN(vec3) solar_irradiance_xyz,
                                  Float albedo, IN(vec3) camera, IN(vec3) view_ray, Float d,
                                  IN(vec3) light_direction) {
  Float r = length(camera);
  Float mu = atmClampCosine(dot(camera, view_ray) / r);
  vec4 t4 = transmittanceAlongRay(atm, transmittance_xyz, r, mu, d, true);
  vec3 point = camera + view_ray * d;
  Float r_p = length(point);
  Float mu_s_p = atmClampCosine(dot(point, light_direction) / r_p);
  vec4 light_t = transmittanceToSun(atm, transmittance_xyz, r_p, mu_s_p);
  vec4 sky = lookupIrradiance(atm, irradiance_xyz, r_p, mu_s_p);
  vec3 irradiance = solar_irradiance_xyz * vec3(light_t.x, light_t.y, light_t.z) *
                        max(mu_s_p, 0.0) + vec3(sky.x, sky.y, sky.z);
  return xyzToRec709Linear(albedo * (1.0 / ATMOSPHERE_PI) * irradiance * vec3(t4.x, t4.y, t4.z));
}

// Everything the sky pass shows for one light (Rec.709, cd/m^2): the sky, and either the
// ground the ray meets (reflection attenuated; its in-scatter is in the sky term) or, for the
// sun (with_disc), the limb-darkened disc.
vec3 packedViewRec709(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_xyz,
                      IN(sampler3D) scattering_packed, IN(sampler3D) single_mie_rg,
                      IN(sampler2D) irradiance_xyz, IN(vec3) solar_irradiance_xyz,
                      IN(vec3) limb_darkening_xyz, Float albedo, IN(vec3) camera_position,
                      IN(vec3) view_ray, IN(vec3) light_direction, bool with_disc) {
  vec3 camera = camera_position;
  Float r;
  Float rmu;
  if (!enterAtmosphere(atm, camera, view_ray, r, rmu)) {
    return with_disc ? xyzToRec709Linear(packedSunDiscXyz(atm, transmittance_xyz,
                                                          solar_irradiance_xyz, limb_darkening_xyz,
                                                          camera_position, view_ray, light_direction))
                     : vec3(0.0);
  }
  vec3 rgb = packedSkyInsideRec709(atm, scattering_packed, single_mie_rg, camera, r, rmu, view_ray,
                                   light_direction);
  Float discriminant = rmu * rmu - r * r + atm.bottom_radius * atm.bottom_radius;
  if (rmu < 0.0 && discriminant >= 0.0) {
    return rgb + packedGroundReflectionRec709(atm, transmittance_xyz, irradiance_xyz,
                                              solar_irradiance_xyz, albedo, camera, view_ray,
                                              -rmu - sqrt(discriminant), light_direction);
  }
  if (with_disc) {
    rgb += xyzToRec709Linear(packedSunDiscXyz(atm, transmittance_xyz, solar_irradiance_xyz,
                                              limb_darkening_xyz, camera, view_ray,
                                              light_direction));
  }
  return rgb;
}

#endif
