#include "ephemeris/refraction.h"
#include "physics/common/units.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::ephemeris {

double refractionScale(double pressureHpa, double temperatureC) {
  if (!(std::isfinite(pressureHpa) && pressureHpa >= 0.0 && pressureHpa < 2000.0))
    throw std::invalid_argument("refraction: pressure " + std::to_string(pressureHpa) +
                                " hPa is outside [0, 2000)");
  if (!(std::isfinite(temperatureC) && temperatureC > -100.0 && temperatureC < 100.0))
    throw std::invalid_argument("refraction: temperature " + std::to_string(temperatureC) +
                                " C is outside (-100, 100)");
  return (pressureHpa / 1010.0) * (283.0 / (273.0 + temperatureC));
}

double refractionSaemundsson(double altitudeRad, double pressureHpa, double temperatureC) {
  if (!std::isfinite(altitudeRad))
    throw std::invalid_argument("refraction: altitude " + std::to_string(altitudeRad) + " is not finite");
  const double scale = refractionScale(pressureHpa, temperatureC);
  using skyig::kDegPerRad;
  const double h = std::max(altitudeRad, kRefractionFloorRad) * kDegPerRad;  // degrees
  if (h >= 90.0) return 0.0;
  const double arcmin = 1.02 / std::tan((h + 10.3 / (h + 5.11)) / kDegPerRad) + 0.0019279;
  const double fade = altitudeRad >= kRefractionFloorRad
                          ? 1.0
                          : std::max(0.0, (altitudeRad - kRefractionZeroRad) / (kRefractionFloorRad - kRefractionZeroRad));
  return std::max(arcmin, 0.0) * scale * fade / 60.0 / kDegPerRad;
}

double refractionAtApparent(double apparentRad, double pressureHpa, double temperatureC) {
  double a = apparentRad;
  for (int i = 0; i < 60; ++i) {
    const double next = apparentRad - refractionSaemundsson(a, pressureHpa, temperatureC);
    if (next == a) break;
    a = next;
  }
  return apparentRad - a;
}

RefractionExpansion refractionExpansion(double apparentRad, double airlessRad, double radiusRad,
                                        double pressureHpa, double temperatureC) {
  if (!(std::isfinite(radiusRad) && radiusRad > 0.0))
    throw std::invalid_argument("refraction: disc radius " + std::to_string(radiusRad) + " rad is not positive");
  const double h0 = apparentRad, step = radiusRad;
  const double r0 = apparentRad - airlessRad;
  const double up = refractionAtApparent(h0 + step, pressureHpa, temperatureC);
  const double down = refractionAtApparent(h0 - step, pressureHpa, temperatureC);
  const double centre = refractionAtApparent(h0, pressureHpa, temperatureC);  // the same formula's, for the curvature
  return {h0, r0, (up - down) / (2.0 * step), (up - 2.0 * centre + down) / (2.0 * step * step)};
}

}  // namespace skyig::ephemeris
