// Aerial perspective from the renderer's packed tables (rendering_rec709.glsl): the light
// scattered into the segment between the camera and a point, in linear Rec.709. Bruneton &
// Neyret (2008), section 4 ("aerial perspective"): with the tables S(x, v, s) of the light
// scattered towards x along -v from the whole ray,
//   S[x -> x_p] = S(x, v, s) - T(x, x_p) S(x_p, v, s),
// as Bruneton's 2017 GetSkyRadianceToPoint computes it (rendering.glsl: skyRadianceToPoint,
// which the CPU's AtmosphereModel::skyRadianceToPoint runs on the spectral tables in double).
// Here the tables hold the Rec.709 sum over the wavelengths, so T is one factor per Rec.709
// channel, that of sunlight (the caller's): T S(x_p) is exact for light of the sun's spectrum
// and an approximation for the sky's.
#ifndef SKYIG_ATMOSPHERE_AERIAL_PERSPECTIVE_GLSL
#define SKYIG_ATMOSPHERE_AERIAL_PERSPECTIVE_GLSL
#include "physics/atmosphere/rendering_rec709.glsl"

// The segment from camera_position to the point `offset` metres from it (on the axes of
// camera_position, which is relative to the planet's centre), from where it enters the
// atmosphere (camera, at radius r; mu the cosine of its zenith angle) over d metres. False when
// there is none (a point at the camera, a ray that misses the atmosphere). The point
// camera + offset is never formed: in single precision, at the planet's radius, it would be
// half a metre off (half a percent of a 100 m segment).
bool aerialSegment(IN(AtmosphereParameters) atm, IN(vec3) camera_position, IN(vec3) offset,
                   OUT(vec3) camera, OUT(vec3) view_ray, OUT(Float) r, OUT(Float) mu, OUT(Float) d,
                   OUT(bool) ray_r_mu_intersects_ground) {
  Float segment = length(offset);
  view_ray = offset / max(segment, 1e-30);
  camera = camera_position;
  Float rmu_camera = dot(camera_position, view_ray);
  Float rmu;
  r = length(camera);
  mu = 1.0;
  d = 0.0;
  ray_r_mu_intersects_ground = false;
  if (segment <= 0.0 || !enterAtmosphere(atm, camera, view_ray, r, rmu)) {
    return false;
  }
  // What the camera moved to enter the atmosphere comes off the segment (rmu grows by it).
  d = max(segment - (rmu - rmu_camera), 0.0);
  mu = atmClampCosine(rmu / r);
  ray_r_mu_intersects_ground = rayIntersectsGround(atm, r, mu);
  return true;
}

// Rec.709 radiance (cd/m^2) scattered towards the camera along the segment, lit from
// light_direction, given the segment's transmittance per Rec.709 channel.
vec3 packedInScatteredRec709(IN(AtmosphereParameters) atm, IN(sampler3D) scattering_packed,
                             IN(sampler3D) single_mie_rg, IN(vec3) camera, IN(vec3) view_ray,
                             Float r, Float mu, Float d, bool ray_r_mu_intersects_ground,
                             IN(vec3) light_direction, IN(vec3) transmittance) {
  Float mu_s = atmClampCosine(dot(camera, light_direction) / r);
  Float nu = atmClampCosine(dot(view_ray, light_direction));
  vec4 uvwz = scatteringUvwzFromRMuMuSNu(atm, r, mu, mu_s, nu, ray_r_mu_intersects_ground);
  vec4 s = lookupScatteringUvwz(atm, scattering_packed, uvwz);
  vec4 m = lookupScatteringUvwz(atm, single_mie_rg, uvwz);
  Float r_p = radiusAtDistance(atm, r, mu, d);
  Float mu_p = atmClampCosine((r * mu + d) / r_p);
  Float mu_s_p = atmClampCosine((r * mu_s + d * nu) / r_p);
  vec4 uvwz_p = scatteringUvwzFromRMuMuSNu(atm, r_p, mu_p, mu_s_p, nu, ray_r_mu_intersects_ground);
  vec4 s_p = lookupScatteringUvwz(atm, scattering_packed, uvwz_p);
  vec4 m_p = lookupScatteringUvwz(atm, single_mie_rg, uvwz_p);
  // C* and C_M apart, each clamped at zero as the spectral version does.
  vec3 rayleigh = max(vec3(s.x, s.y, s.z) - transmittance * vec3(s_p.x, s_p.y, s_p.z), vec3(0.0));
  vec3 mie = max(vec3(m.x, m.y, s.w) - transmittance * vec3(m_p.x, m_p.y, s_p.w), vec3(0.0));
  return (rayleigh * rayleighPhaseFunction(nu) + mie * miePhaseFunction(atm, nu)) *
         (1.0 / REC709_TABLE_SCALE);
}

#endif
