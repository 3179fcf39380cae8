#include "physics/stars/star_field.h"

#include "ephemeris/refraction.h"
#include "physics/stars/star_colour.h"
#include "physics/stars/star_photometry.h"
#include "physics/stars/star_scintillation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace skyig::sky::night {

namespace {

// Below this airless altitude nothing is seen even from 100 km up (dip of the horizon 10 deg).
constexpr double kLowestSine = -0.2079116908177593;  // sin(-12 degrees)

double luminance(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Of a unit vector (asin, not atan2 and hypot: this runs 9000 times a state).
double altitudeOf(const glm::dvec3& d) { return std::asin(std::clamp(d.z, -1.0, 1.0)); }

// One source seen through the atmosphere, or false when no light of it arrives.
bool seen(const glm::dvec3& airless, const glm::dvec3& rec709Lux, double temperatureK, int id,
          const ephemeris::Observer& observer, const atmosphere::ExtinctionProfile& extinction,
          const StarFieldOptions& options, PointSource& out) {
  if (airless.z < kLowestSine) return false;
  const double altitude = altitudeOf(airless);
  const glm::dvec3 transmitted = rec709Lux * extinction.rec709(altitude) * options.intensity;
  if (luminance(transmitted) <= 0.0) return false;
  out.direction = refractedDirection(airless, observer.pressureHpa, observer.temperatureC);
  const double twinkle =
      options.scintillation ? scintillationFactor(id, options.timeS, airmassKastenYoung(altitudeOf(out.direction))) : 1.0;
  out.rec709Lux = transmitted * twinkle;
  out.illuminanceLux = luminance(out.rec709Lux);
  out.temperatureK = temperatureK;
  return true;
}

}  // namespace

glm::dvec3 refractedDirection(const glm::dvec3& airless, double pressureHpa, double temperatureC) {
  const double altitude = altitudeOf(airless);
  const double apparent = altitude + ephemeris::refractionSaemundsson(altitude, pressureHpa, temperatureC);
  const double horizontal = std::sqrt(airless.x * airless.x + airless.y * airless.y);
  if (horizontal <= 0.0) return airless;  // the zenith or nadir: refraction vanishes there
  return {airless.x / horizontal * std::cos(apparent), airless.y / horizontal * std::cos(apparent), std::sin(apparent)};
}

StarField buildStarField(const StarCatalogue* catalogue, const ephemeris::SkyEphemeris& sky,
                         const atmosphere::ExtinctionProfile& extinction, const StarFieldOptions& options) {
  if (!(options.intensity >= 0.0 && options.intensity <= 1.0))
    throw std::invalid_argument("star field intensity " + std::to_string(options.intensity) + " is outside [0, 1]");
  StarField field;
  if (options.intensity == 0.0) return field;
  PointSource p;
  if (catalogue) {
    const glm::dvec3 aberration(sky.aberrationJ2000.x, sky.aberrationJ2000.y, sky.aberrationJ2000.z);
    const auto& m = sky.j2000ToEnu.m;
    field.stars.reserve(catalogue->stars().size() / 2);
    for (const CatalogueStar& s : catalogue->stars()) {
      const glm::dvec3 u = glm::normalize(s.directionJ2000 + aberration);
      const glm::dvec3 enu(m[0] * u.x + m[1] * u.y + m[2] * u.z, m[3] * u.x + m[4] * u.y + m[5] * u.z,
                           m[6] * u.x + m[7] * u.y + m[8] * u.z);
      if (seen(enu, s.rec709PerLux * s.illuminanceLux, s.temperatureK, s.hr, sky.observer, extinction, options, p))
        field.stars.push_back(p);
    }
  }
  static const std::array<glm::dvec3, 5> planetColours = [] {
    std::array<glm::dvec3, 5> c;
    for (int i = 0; i < 5; ++i) c[i] = starRec709FromBv(kPlanetBMinusV[i]);
    return c;
  }();
  for (int i = 0; i < 5; ++i) {
    const ephemeris::PlanetState& planet = sky.planets[static_cast<std::size_t>(i)];
    const glm::dvec3 enu(planet.enu.x, planet.enu.y, planet.enu.z);
    // Planets twinkle far less than stars (their discs average the turbulence): none here.
    StarFieldOptions steady = options;
    steady.scintillation = false;
    if (seen(enu, planetColours[static_cast<std::size_t>(i)] * illuminanceFromVMagnitude(planet.magnitude),
             starTemperatureFromBv(kPlanetBMinusV[i]), -1 - i, sky.observer, extinction, steady, p))
      field.planets.push_back(p);
  }
  return field;
}

glm::dvec3 horizontalIlluminance(const StarField& field) {
  glm::dvec3 e(0.0);
  for (const auto* list : {&field.stars, &field.planets})
    for (const PointSource& p : *list) e += p.rec709Lux * std::max(p.direction.z, 0.0);
  return e;
}

}  // namespace skyig::sky::night
