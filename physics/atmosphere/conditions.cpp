#include "physics/atmosphere/conditions.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace skyig::atmosphere {

namespace {

[[noreturn]] void bad(const char* name, double value, const char* expected) {
  std::ostringstream msg;
  msg << "atmosphere conditions: " << name << " = " << value << " is invalid (expected "
      << expected << ")";
  throw std::invalid_argument(msg.str());
}

}  // namespace

double mieExtinctionForVisibility(const Medium& medium, double visibilityKm) {
  const double rayleigh = coefficientsAt(medium, 550.0).rayleighScattering;
  const double limitKm = kKoschmiederConstant / rayleigh / 1000.0;
  if (!(visibilityKm > 0.0) || !(visibilityKm < limitKm)) {
    std::ostringstream expected;
    expected << "in (0, " << limitKm << ") km, the clean-air limit";
    bad("visibility_km", visibilityKm, expected.str().c_str());
  }
  const double total = kKoschmiederConstant / (visibilityKm * 1000.0);
  // The Angstrom law of coefficientsAt is referred to 550 nm, so this is the 550 nm value.
  return total - rayleigh;
}

double visibilityOf(const Medium& medium) {
  const SpectralCoefficients c = coefficientsAt(medium, 550.0);
  return kKoschmiederConstant / (c.rayleighScattering + c.mieExtinction) / 1000.0;
}

double humidityGrowthFactor(double rh) {
  if (!(rh >= 0.0 && rh <= 0.99)) bad("relative_humidity", rh, "in [0, 0.99]");
  return std::pow((1.0 - rh) / (1.0 - kReferenceHumidity), -kHanelGamma);
}

Medium applyConditions(const Medium& base, const Conditions& c) {
  Medium m = base;
  if (c.groundAlbedo) {
    if (!(*c.groundAlbedo >= 0.0 && *c.groundAlbedo <= 1.0)) {
      bad("ground_albedo", *c.groundAlbedo, "in [0, 1]");
    }
    m.groundAlbedo = *c.groundAlbedo;
  }
  if (c.visibilityKm) {
    if (c.relativeHumidity) humidityGrowthFactor(*c.relativeHumidity);  // still validated
    m.mieExtinctionPerM = mieExtinctionForVisibility(base, *c.visibilityKm);
  } else if (c.relativeHumidity) {
    m.mieExtinctionPerM = base.mieExtinctionPerM * humidityGrowthFactor(*c.relativeHumidity);
  }
  validate(m);
  return m;
}

}  // namespace skyig::atmosphere
