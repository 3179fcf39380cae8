#pragma once
// Moons for the tests: a disc placed by hand, and instants when the real moon is up at night
// with a given phase, found by scanning the ephemeris (so no position is hard-coded).
#include "ephemeris/ephemeris.h"
#include "physics/atmosphere/medium.h"
#include "physics/moon/moon_disc.h"
#include "sky/sky_state.h"

#include <glm/glm.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include "physics/common/units.h"

namespace skyig::sky::testing {
using namespace skyig::sky::night;

using skyig::kDeg;

inline std::shared_ptr<const atmosphere::ExtinctionProfile> seaLevelExtinction() {
  static const auto profile = std::make_shared<const atmosphere::ExtinctionProfile>(atmosphere::Medium{}, 0.0);
  return profile;
}

inline MoonPlacement placeMoon(double azimuthDeg, double altitudeDeg, double phaseDeg, double limbDeg = 90.0) {
  MoonPlacement p;
  p.azimuthRad = azimuthDeg * kDeg;
  p.altitudeRad = p.altitudeRefractedRad = altitudeDeg * kDeg;
  p.phaseAngleRad = phaseDeg * kDeg;
  p.brightLimbAngleRad = limbDeg * kDeg;
  return p;
}

// The first hour of days 1-28 of `year` from `month` on (two months: more than a lunation) when
// the sun is below -12 deg and the moon above `minAltitudeDeg` with a phase angle in
// [phaseMinDeg, phaseMaxDeg]. Innsbruck by default.
inline std::optional<ObserverState> nightWithMoon(double phaseMinDeg, double phaseMaxDeg, double minAltitudeDeg,
                                                  int year = 2026, int month = 1) {
  ObserverState o;
  ephemeris::Observer where;
  where.latitudeRad = o.latitudeDeg * kDeg;
  where.longitudeRad = o.longitudeDeg * kDeg;
  where.heightM = o.heightM;
  for (int m = month; m < month + 2; ++m)
    for (int day = 1; day <= 28; ++day)
      for (int hour = 0; hour < 24; ++hour) {
        const ephemeris::UtcTime t{year, m, day, hour * 3600.0};
        const ephemeris::SkyEphemeris sky = ephemeris::computeEphemeris(t, where);
        const double phase = sky.moon.phaseAngleRad / kDeg;
        if (sky.sun.altitudeRad < -12.0 * kDeg && sky.moon.altitudeRad > minAltitudeDeg * kDeg &&
            phase >= phaseMinDeg && phase <= phaseMaxDeg) {
          o.utc = t;
          return o;
        }
      }
  return std::nullopt;
}

// The disc's illuminance at normal incidence from its radiance (after extinction): a midpoint
// sum over a gnomonic grid around the seen centre (solid angle of a cell da / (1 + x^2 + y^2)^1.5).
inline double integratedLux(const MoonDisc& d, int grid) {
  const glm::dvec3 c = d.centreSeen;
  const glm::dvec3 right = glm::normalize(glm::cross(c, glm::dvec3(0, 0, 1)));
  const glm::dvec3 up = glm::cross(right, c);
  const double half = 1.01 * std::tan(d.angularRadiusRad), step = 2.0 * half / grid;
  double sum = 0.0;
  for (int i = 0; i < grid; ++i)
    for (int j = 0; j < grid; ++j) {
      const double x = -half + (i + 0.5) * step, y = -half + (j + 0.5) * step;
      const double l = moonDiscRadiance(d, c + x * right + y * up).luminanceCdM2;
      sum += l * step * step / std::pow(1.0 + x * x + y * y, 1.5);
    }
  return sum;
}

}  // namespace skyig::sky::testing
