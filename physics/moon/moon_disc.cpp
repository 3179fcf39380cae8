#include "physics/moon/moon_disc.h"

#include "ephemeris/night_irradiance.h"
#include "physics/moon/moon_physics.h"
#include "physics/moon/moon_light.h"
#include "physics/common/common_physics.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::sky::night {

namespace {

constexpr double kAuKm = 149597870.7;

void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument(what);
}

glm::dvec3 fromVec3(const ephemeris::Vec3& v) { return {v.x, v.y, v.z}; }

glm::dvec3 direction(double azimuth, double altitude) {
  return {std::cos(altitude) * std::sin(azimuth), std::cos(altitude) * std::cos(azimuth), std::sin(altitude)};
}

// Unit vector in the plane of the sky at `centre` towards `v`'s projection; `fallback` when v
// is along the centre.
glm::dvec3 skyPlaneDirection(const glm::dvec3& v, const glm::dvec3& centre, const glm::dvec3& fallback) {
  const glm::dvec3 p = v - glm::dot(v, centre) * centre;
  const double l = glm::length(p);
  return l > 1e-9 ? p / l : fallback;
}

void validate(const MoonPlacement& p) {
  auto finite = [](double v) { return std::isfinite(v); };
  require(finite(p.azimuthRad), "moon azimuth " + std::to_string(p.azimuthRad) + " rad is not finite");
  require(finite(p.altitudeRad) && std::abs(p.altitudeRad) <= 0.5 * std::numbers::pi,
          "moon altitude " + std::to_string(p.altitudeRad) + " rad is outside [-pi/2, pi/2]");
  require(finite(p.altitudeRefractedRad) && std::abs(p.altitudeRefractedRad - p.altitudeRad) < 0.05,
          "moon refracted altitude " + std::to_string(p.altitudeRefractedRad) + " rad is not within 3 deg of the airless one");
  require(finite(p.distanceKm) && p.distanceKm > 3.0e5 && p.distanceKm < 4.2e5,
          "moon distance " + std::to_string(p.distanceKm) + " km is outside (300000, 420000)");
  require(finite(p.phaseAngleRad) && p.phaseAngleRad >= 0.0 && p.phaseAngleRad <= std::numbers::pi,
          "moon phase angle " + std::to_string(p.phaseAngleRad) + " rad is outside [0, pi]");
  require(finite(p.brightLimbAngleRad), "moon bright-limb angle " + std::to_string(p.brightLimbAngleRad) + " is not finite");
  require(finite(p.sunMoonDistanceKm) && p.sunMoonDistanceKm > 1.0e8 && p.sunMoonDistanceKm < 2.0e8,
          "sun-moon distance " + std::to_string(p.sunMoonDistanceKm) + " km is outside (1e8, 2e8)");
  ephemeris::refractionScale(p.pressureHpa, p.temperatureC);  // throws naming a bad pressure or temperature
  const double l = glm::length(p.eclipticPoleEnu);
  require(std::isfinite(l) && std::abs(l - 1.0) < 1e-6, "ecliptic pole is not a unit vector");
}

// The sunlit Lommel-Seeliger irradiance with and without the albedo map: their ratio makes the
// map keep eq. 9's total at this phase and orientation (the maria are not spread evenly, so a
// crescent would otherwise be off by ~10%). A midpoint rule over the lune that is both lit and
// visible, in longitude about the axis normal to the sun and the observer, so a thin crescent is
// sampled as finely as a full moon; the weight mu cos(beta) is the projected area. Computed in
// the moon's frame (x towards the observer, y east, z north): it depends on the sun's direction
// there alone.
double albedoNormalisation(const glm::dvec3& sun, const MoonAlbedo& albedo) {
  constexpr int kLongitudes = 48, kLatitudes = 48;
  const glm::dvec3 e1(1.0, 0.0, 0.0), east(0.0, 1.0, 0.0), north(0.0, 0.0, 1.0);
  glm::dvec3 axis = glm::cross(e1, sun);
  if (glm::length(axis) < 1e-9) axis = north;
  axis = glm::normalize(axis);
  const glm::dvec3 e2 = glm::cross(axis, e1);
  const double sunLongitude = std::atan2(glm::dot(sun, e2), glm::dot(sun, e1));
  const double half = 0.5 * std::numbers::pi;
  const double lo = std::max(-half, sunLongitude - half), hi = std::min(half, sunLongitude + half);
  if (hi <= lo) return 1.0;
  double plain = 0.0, mapped = 0.0;
  for (int i = 0; i < kLongitudes; ++i) {
    const double lambda = lo + (hi - lo) * (i + 0.5) / kLongitudes;
    for (int j = 0; j < kLatitudes; ++j) {
      const double beta = std::numbers::pi * ((j + 0.5) / kLatitudes - 0.5);
      const glm::dvec3 n = std::cos(beta) * (std::cos(lambda) * e1 + std::sin(lambda) * e2) + std::sin(beta) * axis;
      const double mu = glm::dot(n, e1);
      const double w = shader::lommelSeeliger(glm::dot(n, sun), mu) * mu * std::cos(beta);
      const glm::dvec2 uv = shader::selenographicUv(n, e1, north, east);
      plain += w;
      mapped += w * albedo.sample(uv.x, uv.y);
    }
  }
  return mapped > 0.0 ? plain / mapped : 1.0;
}

// The same, for the sun's direction in the moon's frame rounded to 1e-4 (0.006 deg) and kept
// per thread: the sun moves that far in the moon's frame in ~15 s, so frames of a running
// simulation reuse it, and the rounding makes the result independent of what came before.
double cachedAlbedoNormalisation(const MoonDisc& d, const MoonAlbedo& albedo) {
  const glm::dvec3 local(glm::dot(d.towardSun, -d.centre), glm::dot(d.towardSun, d.east), glm::dot(d.towardSun, d.north));
  const glm::dvec3 key = glm::round(local * 1e4);
  thread_local struct {
    glm::dvec3 key{-1e9};
    const MoonAlbedo* albedo = nullptr;
    double value = 1.0;
  } cache;
  if (cache.albedo != &albedo || cache.key != key) {
    cache.value = albedoNormalisation(glm::normalize(key), albedo);
    cache.key = key;
    cache.albedo = &albedo;
  }
  return cache.value;
}

// The ephemeris' refraction about the disc's apparent centre (physics/common/refraction.glsl,
// unrefractView), over the moon's radius: at the centre it is the ephemeris' own lift, so the
// disc is drawn where the ephemeris says.
glm::dvec4 refractionNear(const MoonPlacement& p) {
  const ephemeris::RefractionExpansion r =
      ephemeris::refractionExpansion(p.altitudeRefractedRad, p.altitudeRad, 0.0045, p.pressureHpa, p.temperatureC);
  return {r.centreRad, r.refraction, r.slope, r.halfCurvature};
}

}  // namespace

MoonPlacement moonPlacement(const ephemeris::SkyEphemeris& sky) {
  MoonPlacement p;
  p.azimuthRad = sky.moon.azimuthRad;
  p.altitudeRad = sky.moon.altitudeRad;
  p.altitudeRefractedRad = sky.moon.altitudeRefractedRad;
  p.distanceKm = sky.moon.distanceKm;
  p.phaseAngleRad = sky.moon.phaseAngleRad;
  p.brightLimbAngleRad = sky.moon.brightLimbAngleRad;
  p.sunMoonDistanceKm = sunMoonDistanceKm(sky);
  // The ecliptic's north pole in J2000 (obliquity 23.4393 deg, IAU 2006), carried to the horizon.
  const double eps = 23.4392794 * std::numbers::pi / 180.0;
  p.eclipticPoleEnu = glm::normalize(fromVec3(sky.j2000ToEnu * ephemeris::Vec3{0.0, -std::sin(eps), std::cos(eps)}));
  p.pressureHpa = sky.observer.pressureHpa;
  p.temperatureC = sky.observer.temperatureC;
  return p;
}

MoonDisc makeMoonDisc(const MoonPlacement& p, std::shared_ptr<const atmosphere::ExtinctionProfile> extinction,
                      const MoonAlbedo& albedo) {
  validate(p);
  MoonDisc d;
  d.centre = direction(p.azimuthRad, p.altitudeRad);
  d.centreSeen = direction(p.azimuthRad, p.altitudeRefractedRad);
  const double sinRadius = ephemeris::kMoonRadiusKm / p.distanceKm;
  d.angularRadiusRad = std::asin(sinRadius);
  // The sun seen from the moon: phase angle from the observer's direction, towards the bright
  // limb (ephemeris convention: from the zenith direction, counterclockwise as seen, i.e. left).
  const glm::dvec3 up = skyPlaneDirection(glm::dvec3(0, 0, 1), d.centre, glm::dvec3(0, 1, 0));
  const glm::dvec3 left = glm::cross(up, d.centre);
  const glm::dvec3 limb = std::cos(p.brightLimbAngleRad) * up + std::sin(p.brightLimbAngleRad) * left;
  d.towardSun = std::cos(p.phaseAngleRad) * -d.centre + std::sin(p.phaseAngleRad) * limb;
  d.north = skyPlaneDirection(p.eclipticPoleEnu, d.centre, up);
  d.east = glm::cross(d.north, -d.centre);  // selenographic east is the observer's west limb
  d.refraction = refractionNear(p);
  d.extinction = std::move(extinction);
  d.albedo = &albedo;

  // Irradiances in lux: sunlight at the moon, and earthlight at the moon (eq. 9's own law for
  // the earth, Bond albedo 0.3, at the earth's phase pi - phi seen from the moon).
  const double sunAtMoon = shader::SOLAR_ILLUMINANCE_LX * (kAuKm / p.sunMoonDistanceKm) * (kAuKm / p.sunMoonDistanceKm);
  const double re = ephemeris::kEarthRadiusKm / p.distanceKm;
  const double earthAtMoon = 2.0 / 3.0 * ephemeris::kEarthAlbedo * re * re * sunAtMoon *
                             ephemeris::lunarPhaseLaw(std::numbers::pi - p.phaseAngleRad);
  const glm::dvec3& colour = moonlightColour();
  // Lommel-Seeliger over the disc, its total the measured moon's (ephemeris::
  // lunarOppositionFactor: Krisciunas & Schaefer 1991).
  d.sunlitScale = shader::MOON_RADIANCE_COEFFICIENT * sunAtMoon * ephemeris::lunarOppositionFactor(p.phaseAngleRad) *
                  cachedAlbedoNormalisation(d, albedo) * colour;
  d.earthshineScale = shader::MOON_RADIANCE_COEFFICIENT * earthAtMoon * colour;
  // Eq. 9 for the sunlit part, with the measured phase function; the earthshine is lit from the earth's direction (phase 0), where
  // eq. 9 applies the sun's phase law to it too (a difference of 1% of the total at 170 deg, less before).
  const double disc = 2.0 / 3.0 * shader::MOON_ALBEDO_CA * sinRadius * sinRadius;
  d.irradianceRec709 = disc *
                       (sunAtMoon * ephemeris::lunarPhaseLaw(p.phaseAngleRad) * ephemeris::lunarOppositionFactor(p.phaseAngleRad) + earthAtMoon) *
                       colour;
  return d;
}

MoonRadiance moonDiscRadiance(const MoonDisc& d, const glm::dvec3& viewEnu) {
  const double l = glm::length(viewEnu);
  if (!(l > 0.0) || !std::isfinite(l)) throw std::invalid_argument("moon view direction has length " + std::to_string(l));
  const glm::dvec3 view = shader::unrefractView(viewEnu / l, d.refraction);
  const double sinRadius = std::sin(d.angularRadiusRad);
  if (glm::dot(view, d.centre) <= 0.0) return {};
  const glm::dvec3 q = shader::moonDiscOffset(view, d.centre, sinRadius);
  if (glm::dot(q, q) >= 1.0) return {};
  const glm::dvec3 n = shader::moonSurfaceNormal(q, d.centre);
  const glm::dvec2 uv = shader::selenographicUv(n, -d.centre, d.north, d.east);
  const double a = d.albedo ? d.albedo->sample(uv.x, uv.y) : 1.0;
  glm::dvec3 rgb = shader::moonSurfaceRadiance(n, -d.centre, d.towardSun, a, d.sunlitScale, d.earthshineScale);
  if (d.extinction) rgb *= d.extinction->rec709(std::asin(std::clamp(view.z, -1.0, 1.0)));
  return {rgb, shader::rec709Luminance(rgb)};
}

glm::dvec3 moonNormalIlluminanceRec709(const MoonDisc& d) {
  if (d.centreSeen.z <= 0.0) return glm::dvec3(0.0);
  glm::dvec3 e = d.irradianceRec709;
  if (d.extinction) e *= d.extinction->rec709(std::asin(std::clamp(d.centre.z, -1.0, 1.0)));
  return e;
}

double moonIlluminanceLux(const MoonDisc& d) {
  const double seenAltitude = std::asin(std::clamp(d.centreSeen.z, -1.0, 1.0));
  if (seenAltitude <= 0.0) return 0.0;
  return shader::rec709Luminance(moonNormalIlluminanceRec709(d)) * std::sin(seenAltitude);
}


}  // namespace skyig::sky::night
