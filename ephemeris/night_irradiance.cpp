#include "ephemeris/night_irradiance.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::ephemeris {

double lunarPhaseLaw(double phi) {
  phi = std::clamp(phi, 0.0, 3.14159265358979323846);
  if (phi < 1e-9) return 1.0;  // the product tends to 0 at full moon
  const double h = 0.5 * phi;
  const double cotQuarter = 1.0 / std::tan(0.25 * phi);
  if (cotQuarter <= 1.0) return 0.0;  // new moon: ln(cot(pi/4)) = 0 times an infinite tangent
  return std::max(0.0, 1.0 - std::sin(h) * std::tan(h) * std::log(cotQuarter));
}

double lunarMagnitude(double phaseAngleRad) {
  const double phiDeg = std::clamp(phaseAngleRad, 0.0, 3.14159265358979323846) * 180.0 / 3.14159265358979323846;
  return -12.73 + 0.026 * phiDeg + 4e-9 * std::pow(phiDeg, 4.0);
}

double lunarPhaseFunction(double phaseAngleRad) {
  return std::pow(10.0, -0.4 * (lunarMagnitude(phaseAngleRad) - lunarMagnitude(0.0)));
}

double lunarOppositionFactor(double phaseAngleRad) {
  const double lommelSeeliger = lunarPhaseLaw(phaseAngleRad);
  if (!(lommelSeeliger > 1e-9)) return 0.0;
  const double r = kMoonRadiusKm / kMeanMoonDistanceKm;
  const double eq9 = 2.0 / 3.0 * kMoonAlbedo * r * r * kSolarConstantWm2 * lommelSeeliger;
  return irradianceFromMagnitude(lunarMagnitude(phaseAngleRad)) / eq9;
}

double moonIrradiance(double phaseAngleRad, double moonDistanceKm, double sunMoonDistanceKm) {
  constexpr double kAuKm = 149597870.7;
  const double sunAtMoon = kSolarConstantWm2 * (kAuKm / sunMoonDistanceKm) * (kAuKm / sunMoonDistanceKm);
  // Earthshine at the moon: the same reflection law for the earth, seen from the moon.
  const double pi = 3.14159265358979323846;
  const double earthAtMoon = 2.0 / 3.0 * kEarthAlbedo * (kEarthRadiusKm / moonDistanceKm) *
                             (kEarthRadiusKm / moonDistanceKm) * sunAtMoon * lunarPhaseLaw(pi - phaseAngleRad);
  return 2.0 / 3.0 * kMoonAlbedo * (kMoonRadiusKm / moonDistanceKm) * (kMoonRadiusKm / moonDistanceKm) *
         (sunAtMoon * lunarPhaseLaw(phaseAngleRad) * lunarOppositionFactor(phaseAngleRad) + earthAtMoon);
}

double irradianceFromMagnitude(double m) { return std::pow(10.0, -(m + 19.0) / 2.5); }

double magnitudeFromIrradiance(double e) { return -(19.0 + 2.5 * std::log10(e)); }

double colourTemperatureFromBv(double bv) {
  if (!(bv > -0.4 && bv < 10.0))
    throw std::invalid_argument("colour index B-V " + std::to_string(bv) + " is outside (-0.4, 10)");
  return 7000.0 / (bv + 0.56);
}

}  // namespace skyig::ephemeris
