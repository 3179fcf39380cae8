// Rendering from the precomputed tables (Bruneton & Neyret 2008, section 5
// without light shafts): sky radiance along a view ray, radiance scattered between the viewer
// and a point (aerial perspective), and sun and sky irradiance at a point. Positions are in
// metres relative to the planet's centre; directions are unit vectors.
//   scattering_texture:   C* = S_R[L0] + S[L+] / P_R  (Rayleigh single + all multiple)
//   single_mie_texture:   C_M = S_M[L0]               (single Mie, sharp forward peak)
#ifndef SKYIG_ATMOSPHERE_RENDERING_GLSL
#define SKYIG_ATMOSPHERE_RENDERING_GLSL
#include "physics/atmosphere/scattering_texture.glsl"
#include "physics/atmosphere/irradiance.glsl"

// Radiance of the sun disc outside the atmosphere (uniform disc; limb darkening is applied by
// the caller), W m^-2 sr^-1 nm^-1.
vec4 solarRadiance(IN(AtmosphereParameters) atm) {
  return atm.solar_irradiance /
         (ATMOSPHERE_PI * atm.sun_angular_radius * atm.sun_angular_radius);
}

// Radiance of the sun disc seen along view_ray from camera: limb darkened, attenuated by the
// transmittance to the top of the atmosphere, zero off the disc or behind the planet.
// Limb darkening after Hestroffer & Magnan 1998 (A&A 333, 338): I(mu)/I(1) = mu^alpha with
// mu the cosine of the heliocentric angle; scaled by (alpha + 2)/2 so the disc's mean is the
// uniform solarRadiance() and its irradiance stays the solar irradiance.
vec4 sunDiscRadiance(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                     IN(vec3) camera_position, IN(vec3) view_ray, IN(vec3) sun_direction) {
  Float cos_angle = dot(view_ray, sun_direction);
  Float cos_radius = cos(atm.sun_angular_radius);
  if (cos_angle < cos_radius) {
    return vec4(0.0);
  }
  // Fraction of the disc radius: sin(angle) / sin(radius).
  Float x = min(sqrt(max(1.0 - cos_angle * cos_angle, 0.0)) / sin(atm.sun_angular_radius), 1.0);
  Float mu = sqrt(max(1.0 - x * x, 0.0));
  vec4 alpha = atm.limb_darkening_exponent;
  vec4 darkening = vec4(pow(mu, alpha.x), pow(mu, alpha.y), pow(mu, alpha.z), pow(mu, alpha.w)) *
                   (alpha + vec4(2.0)) * 0.5;
  Float r = length(camera_position);
  Float mu_view = dot(camera_position, view_ray) / r;
  vec4 transmittance = vec4(1.0);
  if (r <= atm.top_radius) {
    if (rayIntersectsGround(atm, r, mu_view)) {
      return vec4(0.0);
    }
    transmittance = transmittanceToTopAtmosphereBoundary(atm, transmittance_texture, r, mu_view);
  } else {
    // From space: the planet's disc hides the sun; otherwise the ray may graze the atmosphere.
    Float rmu = r * mu_view;
    Float discriminant_ground = rmu * rmu - r * r + atm.bottom_radius * atm.bottom_radius;
    if (rmu < 0.0 && discriminant_ground >= 0.0) {
      return vec4(0.0);
    }
    Float discriminant_top = rmu * rmu - r * r + atm.top_radius * atm.top_radius;
    if (rmu < 0.0 && discriminant_top >= 0.0) {
      vec3 entry = camera_position + view_ray * (-rmu - sqrt(discriminant_top));
      transmittance = transmittanceToTopAtmosphereBoundary(atm, transmittance_texture,
                                                           atm.top_radius,
                                                           dot(entry, view_ray) / atm.top_radius);
    }
  }
  return solarRadiance(atm) * darkening * transmittance;
}

// Combined lookup of both tables with their phase functions.
vec4 scatteredRadiance(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_texture,
                       IN(sampler3D) single_mie_texture, Float r, Float mu, Float mu_s,
                       Float nu, bool ray_r_mu_intersects_ground) {
  vec4 scattering = lookupScattering(atm, scattering_texture, r, mu, mu_s, nu,
                                     ray_r_mu_intersects_ground);
  vec4 single_mie = lookupScattering(atm, single_mie_texture, r, mu, mu_s, nu,
                                     ray_r_mu_intersects_ground);
  return scattering * rayleighPhaseFunction(nu) +
         single_mie * miePhaseFunction(atm, nu);
}

// Moves a camera outside the atmosphere to where the view ray enters it. Returns false if
// the ray misses the atmosphere (the radiance is then zero and the transmittance one).
bool enterAtmosphere(IN(AtmosphereParameters) atm, INOUT(vec3) camera, IN(vec3) view_ray,
                     OUT(Float) r, OUT(Float) rmu) {
  r = length(camera);
  rmu = dot(camera, view_ray);
  Float distance_to_top =
      -rmu - sqrt(max(rmu * rmu - r * r + atm.top_radius * atm.top_radius, 0.0));
  Float top_discriminant = rmu * rmu - r * r + atm.top_radius * atm.top_radius;
  if (r > atm.top_radius) {
    if (top_discriminant < 0.0 || distance_to_top <= 0.0) {
      return false;
    }
    camera = camera + view_ray * distance_to_top;
    r = atm.top_radius;
    rmu += distance_to_top;
  }
  return true;
}

// Sky radiance reaching `camera` along -view_ray from the end of the ray (ground or space),
// the light scattered into it only (no sun disc, no ground reflection); `transmittance` is
// that of the whole ray (0 if it ends on the ground).
vec4 skyRadiance(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                 IN(sampler3D) scattering_texture, IN(sampler3D) single_mie_texture,
                 IN(vec3) camera_position, IN(vec3) view_ray, IN(vec3) sun_direction,
                 OUT(vec4) transmittance) {
  vec3 camera = camera_position;
  Float r;
  Float rmu;
  if (!enterAtmosphere(atm, camera, view_ray, r, rmu)) {
    transmittance = vec4(1.0);
    return vec4(0.0);
  }
  Float mu = atmClampCosine(rmu / r);
  Float mu_s = atmClampCosine(dot(camera, sun_direction) / r);
  Float nu = atmClampCosine(dot(view_ray, sun_direction));
  bool ray_r_mu_intersects_ground = rayIntersectsGround(atm, r, mu);
  transmittance = ray_r_mu_intersects_ground
                      ? vec4(0.0)
                      : transmittanceToTopAtmosphereBoundary(atm, transmittance_texture, r, mu);
  return scatteredRadiance(atm, scattering_texture, single_mie_texture, r, mu, mu_s, nu,
                           ray_r_mu_intersects_ground);
}

// Radiance scattered into the segment camera -> point (aerial perspective): the difference
// of the table at the camera and, attenuated, at the point (Bruneton & Neyret 2008, section 3
// rewriting, with x_s = x_0); `transmittance` is that of the segment.
vec4 skyRadianceToPoint(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                        IN(sampler3D) scattering_texture, IN(sampler3D) single_mie_texture,
                        IN(vec3) camera_position, IN(vec3) point, IN(vec3) sun_direction,
                        OUT(vec4) transmittance) {
  // A point at the camera (a viewer standing on the ground looking down) has no segment.
  Float segment = length(point - camera_position);
  if (segment <= 0.0) {
    transmittance = vec4(1.0);
    return vec4(0.0);
  }
  vec3 view_ray = (point - camera_position) / segment;
  vec3 camera = camera_position;
  Float r;
  Float rmu;
  if (!enterAtmosphere(atm, camera, view_ray, r, rmu)) {
    transmittance = vec4(1.0);
    return vec4(0.0);
  }
  Float mu = atmClampCosine(rmu / r);
  Float mu_s = atmClampCosine(dot(camera, sun_direction) / r);
  Float nu = atmClampCosine(dot(view_ray, sun_direction));
  Float d = length(point - camera);
  bool ray_r_mu_intersects_ground = rayIntersectsGround(atm, r, mu);
  transmittance =
      transmittanceAlongRay(atm, transmittance_texture, r, mu, d, ray_r_mu_intersects_ground);

  vec4 scattering = lookupScattering(atm, scattering_texture, r, mu, mu_s, nu,
                                     ray_r_mu_intersects_ground);
  vec4 single_mie = lookupScattering(atm, single_mie_texture, r, mu, mu_s, nu,
                                     ray_r_mu_intersects_ground);
  Float r_p = radiusAtDistance(atm, r, mu, d);
  Float mu_p = atmClampCosine((r * mu + d) / r_p);
  Float mu_s_p = atmClampCosine((r * mu_s + d * nu) / r_p);
  vec4 scattering_p = lookupScattering(atm, scattering_texture, r_p, mu_p, mu_s_p, nu,
                                       ray_r_mu_intersects_ground);
  vec4 single_mie_p = lookupScattering(atm, single_mie_texture, r_p, mu_p, mu_s_p, nu,
                                       ray_r_mu_intersects_ground);
  scattering = max(scattering - transmittance * scattering_p, vec4(0.0));
  single_mie = max(single_mie - transmittance * single_mie_p, vec4(0.0));
  return scattering * rayleighPhaseFunction(nu) +
         single_mie * miePhaseFunction(atm, nu);
}

// Irradiance at `point` on a surface of the given normal: the direct sun (returned) and the
// sky (sky_irradiance; the table holds a horizontal surface, scaled by the fraction of the
// sky the tilted surface sees, (1 + n.up)/2: section 3, "Multiple scattering").
vec4 sunAndSkyIrradiance(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                         IN(sampler2D) irradiance_texture, IN(vec3) point, IN(vec3) normal,
                         IN(vec3) sun_direction, OUT(vec4) sky_irradiance) {
  Float r = length(point);
  Float mu_s = atmClampCosine(dot(point, sun_direction) / r);
  sky_irradiance = lookupIrradiance(atm, irradiance_texture, r, mu_s) *
                   (1.0 + dot(normal, point) / r) * 0.5;
  return atm.solar_irradiance * transmittanceToSun(atm, transmittance_texture, r, mu_s) *
         max(dot(normal, sun_direction), 0.0);
}

// Radiance leaving a Lambertian ground point towards the camera, attenuated and with the
// light scattered in between (aerial perspective): R[L] + S[L] of the rendering equation (eq. 8) for the ground.
vec4 groundRadiance(IN(AtmosphereParameters) atm, IN(sampler2D) transmittance_texture,
                    IN(sampler3D) scattering_texture, IN(sampler3D) single_mie_texture,
                    IN(sampler2D) irradiance_texture, IN(vec3) camera_position,
                    IN(vec3) ground_point, IN(vec4) albedo, IN(vec3) sun_direction,
                    OUT(vec4) transmittance) {
  vec3 normal = normalize(ground_point);
  vec4 sky_irradiance;
  vec4 sun_irradiance = sunAndSkyIrradiance(atm, transmittance_texture, irradiance_texture,
                                            ground_point, normal, sun_direction, sky_irradiance);
  vec4 in_scatter = skyRadianceToPoint(atm, transmittance_texture, scattering_texture,
                                       single_mie_texture, camera_position, ground_point,
                                       sun_direction, transmittance);
  return albedo * (1.0 / ATMOSPHERE_PI) * (sun_irradiance + sky_irradiance) * transmittance +
         in_scatter;
}

#endif
