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

double cleanAirVisibilityKm(const Medium& medium) {
  return kKoschmiederConstant / coefficientsAt(medium, 550.0).rayleighScattering / 1000.0;
}

double mieExtinctionForVisibility(const Medium& medium, double visibilityKm) {
  const double rayleigh = coefficientsAt(medium, 550.0).rayleighScattering;
  if (!(visibilityKm > 0.0) || !std::isfinite(visibilityKm)) bad("visibility_km", visibilityKm, "a finite number > 0");
  // A host's "unlimited" (hundreds of km) is the clearest air there is: no aerosols.
  if (visibilityKm >= cleanAirVisibilityKm(medium)) return 0.0;
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

Medium withAerosolExtinction(const Medium& base, double mieExtinctionPerM) {
  Medium m = base;
  m.mieExtinctionPerM = mieExtinctionPerM;
  if (base.aerosolType != AerosolType::bruneton2017) return m;  // its water is its humidity's
  const double absorption = base.mieExtinctionPerM * (1.0 - base.mieSingleScatteringAlbedo);
  if (mieExtinctionPerM > base.mieExtinctionPerM) m.mieSingleScatteringAlbedo = 1.0 - absorption / mieExtinctionPerM;
  return m;
}

Medium applyConditions(const Medium& base, const Conditions& c) {
  Medium m = base;
  if (c.groundAlbedo) {
    if (!(*c.groundAlbedo >= 0.0 && *c.groundAlbedo <= 1.0)) {
      bad("ground_albedo", *c.groundAlbedo, "in [0, 1]");
    }
    m.groundAlbedo = *c.groundAlbedo;
  }
  if (c.relativeHumidity) humidityGrowthFactor(*c.relativeHumidity);  // validated in every case
  const bool typed = base.aerosolType != AerosolType::bruneton2017;
  if (typed && c.relativeHumidity) {
    // The type's particles at the humidity (OPAC's nearest class): albedo, spectrum and phase
    // function; their extinction grows as OPAC's mixture does between the two humidities.
    const double rh = nearestHumidityClass(*c.relativeHumidity);
    const double growth = aerosolOptics(base.aerosolType, rh).extinctionAt550PerKm /
                          aerosolOptics(base.aerosolType, base.aerosolHumidity).extinctionAt550PerKm;
    m = withAerosolType(m, base.aerosolType, rh);
    m.mieExtinctionPerM = base.mieExtinctionPerM * growth;
  }
  if (c.visibilityKm) {
    m = withAerosolExtinction(m, mieExtinctionForVisibility(base, *c.visibilityKm));
  } else if (c.relativeHumidity && !typed) {
    m = withAerosolExtinction(m, base.mieExtinctionPerM * humidityGrowthFactor(*c.relativeHumidity));
  }
  validate(m);
  return m;
}

}  // namespace skyig::atmosphere
