#pragma once
// Atmospheric refraction from the airless (true) altitude: Saemundsson (1986, Sky & Telescope 72,
// 70), as given by Meeus, Astronomical Algorithms 2nd ed., eq. 16.4 with the +0.0019279 arcmin
// term that makes it vanish at the zenith, scaled by refractionScale below.
// Accurate to about 0.1 arcmin above 5 degrees at standard conditions.

namespace skyig::ephemeris {

// The air at the observer when nobody says otherwise: the ICAO standard atmosphere at sea level
// (ICAO Doc 7488, 1993), which is also CIGI's default for the Atmosphere Control. Every default
// of skyig (the ephemeris observer, the host state, the sky's observer) is this one.
inline constexpr double kStandardPressureHpa = 1013.25;
inline constexpr double kStandardTemperatureC = 15.0;

// Meeus' scaling of refraction from the 1010 hPa, 10 C it is tabulated for (Astronomical
// Algorithms, 2nd ed., p. 107): (P / 1010 hPa) (283 K / T). Throws std::invalid_argument for a
// pressure outside [0, 2000) hPa or a temperature outside (-100, 100) C, naming it.
double refractionScale(double pressureHpa, double temperatureC);

// Lowest true altitude the formula is used at. Below it the refraction at -2 degrees fades
// linearly to zero at -5 degrees: apparent altitude stays continuous and monotonic, and a body
// far below the horizon is not lifted by 44 arcmin.
inline constexpr double kRefractionFloorRad = -2.0 * 3.14159265358979323846 / 180.0;
inline constexpr double kRefractionZeroRad = -5.0 * 3.14159265358979323846 / 180.0;

// Refraction in radians (apparent minus true altitude) for true altitude altitudeRad, pressure
// in hPa and temperature in Celsius. Throws std::invalid_argument for NaN, a negative pressure
// or a temperature at or below -273.15 C.
double refractionSaemundsson(double altitudeRad, double pressureHpa, double temperatureC);

// The same refraction as a function of the apparent altitude h (h = a + R(a)), inverted by
// fixed-point iteration to convergence (|dR/da| < 0.3 wherever R is defined: under 40 steps to
// the last bit). Throws as refractionSaemundsson.
double refractionAtApparent(double apparentRad, double pressureHpa, double temperatureC);

// refractionAtApparent to second order about a disc's apparent centre h0 (its airless altitude
// a0: the lift there is exactly h0 - a0, as the ephemeris or the caller placed it), for drawing a
// disc of about `radiusRad` (the sun's, the moon's) refracted and flattened as it is seen:
// R(h) = refraction + slope (h - h0) + halfCurvature (h - h0)^2, by central differences over the
// radius (physics/common/refraction.glsl, unrefractView). Over half a degree the third-order term
// is below 0.01 arcmin.
struct RefractionExpansion {
  double centreRad = 0.0;      // h0, apparent
  double refraction = 0.0;     // R(h0)
  double slope = 0.0;          // dR/dh at h0
  double halfCurvature = 0.0;  // d2R/dh2 / 2 at h0
};
RefractionExpansion refractionExpansion(double apparentRad, double airlessRad, double radiusRad,
                                        double pressureHpa, double temperatureC);

}  // namespace skyig::ephemeris
