#pragma once
// Low-precision apparent solar position, about 0.01 degree (Meeus, Astronomical Algorithms,
// 2nd ed., ch. 25 "Solar coordinates", low accuracy method, and ch. 12 for sidereal time).
// Good enough to light the analytic sky; the precise ephemeris (VSOP87) supersedes it.
#include "ephemeris/time.h"

namespace skyig::ephemeris {

struct EquatorialPosition {
  double rightAscension = 0.0;  // radians, [0, 2 pi)
  double declination = 0.0;     // radians
  double distanceAu = 1.0;      // astronomical units
};

struct HorizontalPosition {
  double azimuth = 0.0;   // radians, from north through east, [0, 2 pi)
  double altitude = 0.0;  // radians, airless (geometric)
};

// Apparent geocentric right ascension and declination of the sun (Meeus eq. 25.2-25.8).
// jd: Julian date in the dynamical scale (TT); UTC is within about a minute of it, which
// moves the sun by less than 0.001 degree.
EquatorialPosition lowPrecisionSunEquatorial(double jd);

// Greenwich mean sidereal time in radians (Meeus eq. 12.4), jd in UT.
double greenwichMeanSiderealTime(double jdUt);

// Equatorial to horizontal for an observer at geodetic latitude/longitude (radians, east
// positive) at local sidereal angle gmst + longitude (Meeus eq. 13.5-13.6, azimuth from north).
HorizontalPosition equatorialToHorizontal(const EquatorialPosition& eq, double gmst,
                                          double latitude, double longitude);

// The sun seen from a place at a UTC instant.
HorizontalPosition lowPrecisionSunHorizontal(const UtcTime& utc, double latitude, double longitude);

}  // namespace skyig::ephemeris
