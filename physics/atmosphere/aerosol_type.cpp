#include "physics/atmosphere/aerosol_type.h"

#include <cmath>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "physics/atmosphere/medium.h"

namespace skyig::atmosphere {
namespace {

struct HumidityClass {
  int relativeHumidityPct;
  double extinctionAt550PerKm;
  double singleScatteringAlbedo;
  double angstromExponent;
  double asymmetry;
  std::array<double, kMiePhaseSamples> logPhase;
};

struct OpacType {
  const char* name;
  double scaleHeightM;
  std::array<HumidityClass, kOpacHumidityClasses.size()> classes;
};

// In AerosolType's order, after bruneton2017 (a test checks the names).
constexpr OpacType kOpacTypes[] = {
#include "physics/atmosphere/aerosol_type_opac.inc"
};
static_assert(std::size(kOpacTypes) == static_cast<std::size_t>(AerosolType::antarctic));

const OpacType& opacType(AerosolType type) {
  if (type == AerosolType::bruneton2017) {
    throw std::invalid_argument("aerosol type bruneton2017 has no OPAC optics");
  }
  return kOpacTypes[static_cast<int>(type) - 1];
}

double mixLog(double a, double b, double f) { return std::exp((1.0 - f) * std::log(a) + f * std::log(b)); }

}  // namespace

std::string_view aerosolTypeName(AerosolType type) {
  return type == AerosolType::bruneton2017 ? "bruneton2017" : opacType(type).name;
}

std::optional<AerosolType> parseAerosolType(std::string_view name) {
  for (int i = 0; i <= static_cast<int>(AerosolType::antarctic); ++i) {
    const auto type = static_cast<AerosolType>(i);
    if (aerosolTypeName(type) == name) return type;
  }
  return std::nullopt;
}

std::string_view aerosolTypeNames() {
  static const std::string names = [] {
    std::string s = "bruneton2017";
    for (const OpacType& t : kOpacTypes) s += std::string(", ") + t.name;
    return s;
  }();
  return names;
}

double tabulatedPhaseIntegral(const std::array<double, kMiePhaseSamples>& logPhase) {
  // The interpolant of medium.glsl, linear in ln p and in u = sqrt(theta / pi), integrated over
  // the sphere: dOmega = 2 pi sin(theta) dtheta, dtheta = 2 pi u du; midpoint rule, 64 steps a
  // sample (the integrand is smooth within a sample).
  constexpr int kSteps = 64;
  constexpr double kLast = kMiePhaseSamples - 1;
  double sum = 0.0;
  for (int i = 0; i + 1 < kMiePhaseSamples; ++i) {
    for (int j = 0; j < kSteps; ++j) {
      const double f = (j + 0.5) / kSteps;
      const double u = (i + f) / kLast;
      const double theta = kPi * u * u;
      const double p = std::exp((1.0 - f) * logPhase[static_cast<std::size_t>(i)] +
                                f * logPhase[static_cast<std::size_t>(i) + 1]);
      sum += p * 2.0 * kPi * std::sin(theta) * 2.0 * kPi * u / (kLast * kSteps);
    }
  }
  return sum;
}

double nearestHumidityClass(double rh) {
  double best = kOpacHumidityClasses[0];
  for (double c : kOpacHumidityClasses) {
    if (std::abs(c - rh) < std::abs(best - rh)) best = c;
  }
  return best;
}

AerosolOptics aerosolOptics(AerosolType type, double rh) {
  const OpacType& t = opacType(type);
  if (!(rh >= 0.0 && rh <= 0.99)) {
    std::ostringstream msg;
    msg << "aerosol humidity " << rh << " is invalid (expected a relative humidity in [0, 0.99])";
    throw std::invalid_argument(msg.str());
  }
  std::size_t i = 0;
  while (i + 2 < kOpacHumidityClasses.size() && rh > kOpacHumidityClasses[i + 1]) ++i;
  const HumidityClass& a = t.classes[i];
  const HumidityClass& b = t.classes[i + 1];
  const double f = (rh - kOpacHumidityClasses[i]) / (kOpacHumidityClasses[i + 1] - kOpacHumidityClasses[i]);
  AerosolOptics o{};
  o.extinctionAt550PerKm = mixLog(a.extinctionAt550PerKm, b.extinctionAt550PerKm, f);
  o.singleScatteringAlbedo = (1.0 - f) * a.singleScatteringAlbedo + f * b.singleScatteringAlbedo;
  o.angstromExponent = (1.0 - f) * a.angstromExponent + f * b.angstromExponent;
  o.asymmetry = (1.0 - f) * a.asymmetry + f * b.asymmetry;
  o.scaleHeightM = t.scaleHeightM;
  for (std::size_t k = 0; k < o.logPhase.size(); ++k) {
    o.logPhase[k] = (1.0 - f) * a.logPhase[k] + f * b.logPhase[k];
  }
  // A mix of two normalised log tables integrates to 1 only to first order in their difference.
  const double integral = tabulatedPhaseIntegral(o.logPhase);
  for (double& v : o.logPhase) v -= std::log(integral);
  return o;
}

Medium withAerosolType(const Medium& base, AerosolType type, double rh) {
  Medium m = base;
  m.aerosolType = type;
  if (type == AerosolType::bruneton2017) return m;  // the medium's own albedo, spectrum and g
  const AerosolOptics o = aerosolOptics(type, rh);
  m.aerosolHumidity = rh;
  m.mieSingleScatteringAlbedo = o.singleScatteringAlbedo;
  m.mieAngstromExponent = o.angstromExponent;
  m.mieScaleHeightM = o.scaleHeightM;  // miePhaseG stays: Cornette-Shanks', unused with a table
  return m;
}

Medium withStandardAerosol(const Medium& base, AerosolType type, double rh) {
  Medium m = withAerosolType(base, type, rh);
  if (type != AerosolType::bruneton2017) m.mieExtinctionPerM = 1e-3 * aerosolOptics(type, rh).extinctionAt550PerKm;
  return m;
}

}  // namespace skyig::atmosphere
