#include "sky/atmosphere/conditions.h"

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

double mieExtinctionForVisibility(const Medium& medium, double visibility_km) {
  const double rayleigh = coefficientsAt(medium, 550.0).rayleigh_scattering;
  const double limit_km = kKoschmiederConstant / rayleigh / 1000.0;
  if (!(visibility_km > 0.0) || !(visibility_km < limit_km)) {
    std::ostringstream expected;
    expected << "in (0, " << limit_km << ") km, the clean-air limit";
    bad("visibility_km", visibility_km, expected.str().c_str());
  }
  const double total = kKoschmiederConstant / (visibility_km * 1000.0);
  // The Angstrom law of coefficientsAt is referred to 550 nm, so this is the 550 nm value.
  return total - rayleigh;
}

double visibilityOf(const Medium& medium) {
  const SpectralCoefficients c = coefficientsAt(medium, 550.0);
  return kKoschmiederConstant / (c.rayleigh_scattering + c.mie_extinction) / 1000.0;
}

double humidityGrowthFactor(double rh) {
  if (!(rh >= 0.0 && rh <= 0.99)) bad("relative_humidity", rh, "in [0, 0.99]");
  return std::pow((1.0 - rh) / (1.0 - kReferenceHumidity), -kHanelGamma);
}

Medium applyConditions(const Medium& base, const Conditions& c) {
  Medium m = base;
  if (c.ground_albedo) {
    if (!(*c.ground_albedo >= 0.0 && *c.ground_albedo <= 1.0)) {
      bad("ground_albedo", *c.ground_albedo, "in [0, 1]");
    }
    m.ground_albedo = *c.ground_albedo;
  }
  if (c.visibility_km) {
    if (c.relative_humidity) humidityGrowthFactor(*c.relative_humidity);  // still validated
    m.mie_extinction_per_m = mieExtinctionForVisibility(base, *c.visibility_km);
  } else if (c.relative_humidity) {
    m.mie_extinction_per_m = base.mie_extinction_per_m * humidityGrowthFactor(*c.relative_humidity);
  }
  validate(m);
  return m;
}

}  // namespace skyig::atmosphere
