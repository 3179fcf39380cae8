#pragma once
// Photometry of point sources for the night sky (docs/night-sky-stars.md, "Units").
//
// Wang, Ji & Zhang 2011, eq. 11 (printed 10^(-m - 19); corrected to the inverse of their
// eq. 10, ephemeris/night_irradiance.h) gives E = 10^(-(m + 19) / 2.5) W/m^2: Jensen et al.
// (2001)'s "irradiance" of a V-magnitude source, which is in fact a
// luminous quantity divided by a nominal efficacy. The renderer works in lux: a star of V = 0
// gives 2.54e-6 lx above the atmosphere: E_v = 10^(-0.4 (m + 13.99)) lx (Allen's Astrophysical
// Quantities, 4th ed.; Schaefer 1990, PASP 102, 212). The two agree
// when 1 W/m^2 of eq. 11 is 10^((19 - 13.99) / 2.5) = 101.6 lx, i.e. an efficacy of about
// 100 lm/W, close to the 93-105 lm/W of sunlight: eq. 11 is the same law in Jensen's units.
#include <cmath>

namespace skyig::sky::night {

inline constexpr double kZeroMagnitudeLux = 2.54e-6;  // V = 0, above the atmosphere

// Illuminance (lux) above the atmosphere from a V magnitude.
inline double illuminanceFromVMagnitude(double vmag) { return std::pow(10.0, -0.4 * (vmag + 13.99)); }

// Lux per W/m^2 of eq. 11: the conversion that makes eq. 11 and the lux law above agree.
inline double luxPerEq11Watt() { return std::pow(10.0, (19.0 - 13.99) / 2.5); }

}  // namespace skyig::sky::night
