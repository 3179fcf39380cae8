#pragma once
// The colour of a star as linear Rec.709 at unit illuminance: B-V -> effective temperature by
// eq. 12 of Wang, Ji & Zhang 2011 (after Jensen et al. 2001; ephemeris/night_irradiance.h) -> a
// blackbody (Planck) seen through the CIE 1931 2-degree colour matching functions -> Rec.709
// (D65 white).
#include <glm/vec3.hpp>

#include <optional>

namespace skyig::sky::night {

// Linear Rec.709 of a blackbody at `temperatureK`, scaled so its luminance (Y) is 1: multiply
// by an illuminance in lux to get each channel's share. Throws std::invalid_argument for a
// temperature outside [500 K, 1e6 K] or NaN.
glm::dvec3 blackbodyRec709(double temperatureK);

// B-V the catalogue lacks for 310 stars: 0.6, near the catalogue's median, a sun-like white.
inline constexpr double kDefaultBMinusV = 0.6;

// The eq. 12 temperature of `bMinusV` (kDefaultBMinusV when absent), K.
double starTemperatureFromBv(std::optional<double> bMinusV);

// blackbodyRec709 at starTemperatureFromBv(bMinusV).
glm::dvec3 starRec709FromBv(std::optional<double> bMinusV);

}  // namespace skyig::sky::night
