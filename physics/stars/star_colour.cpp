#include "physics/stars/star_colour.h"

#include "ephemeris/night_irradiance.h"
#include "physics/spectrum/spectral_data.h"
#include "physics/spectrum/spectrum.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace skyig::sky::night {

namespace {

// Planck's law up to a constant factor (the result is normalised): lambda^-5 / (e^(hc/lkT) - 1).
double planckShape(double wavelengthNm, double temperatureK) {
  constexpr double kC2 = 1.438776877e-2;  // second radiation constant hc/k, m K (CODATA 2018)
  const double lambda = wavelengthNm * 1e-9;
  return 1.0 / (std::pow(lambda / 1e-6, 5.0) * std::expm1(kC2 / (lambda * temperatureK)));
}

}  // namespace

glm::dvec3 blackbodyRec709(double temperatureK) {
  if (!(temperatureK >= 500.0 && temperatureK <= 1e6))
    throw std::invalid_argument("blackbody temperature " + std::to_string(temperatureK) +
                                " K is outside [500, 1e6]");
  // 5 nm midpoint rule over the CMF table's range: the CMFs are smooth on that scale.
  glm::dvec3 xyz(0.0);
  for (double l = atmosphere::kSpectralDataMinNm + 2.5; l < atmosphere::kSpectralDataMaxNm; l += 5.0)
    xyz += planckShape(l, temperatureK) * atmosphere::cie1931ColourMatching(l);
  return atmosphere::xyzToRec709(xyz / xyz.y);
}

double starTemperatureFromBv(std::optional<double> bMinusV) {
  return ephemeris::colourTemperatureFromBv(bMinusV.value_or(kDefaultBMinusV));
}

glm::dvec3 starRec709FromBv(std::optional<double> bMinusV) { return blackbodyRec709(starTemperatureFromBv(bMinusV)); }

}  // namespace skyig::sky::night
