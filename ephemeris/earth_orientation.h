#pragma once
// Earth orientation: IAU 2006 precession (Fukushima-Williams angles, Hilton et al. 2006; IERS
// Conventions 2010 eq. 5.40), IAU 2000B nutation (McCarthy & Luzum 2003, 77 luni-solar terms plus
// the fixed planetary offset; 1 mas against IAU 2000A over 1995-2050), Earth rotation angle and
// IAU 2006 sidereal time (Capitaine et al. 2005; IERS Conventions 2010 eq. 5.15 and 5.32).
// Polar motion is neglected (< 0.5 arcsec). The "J2000" frame here is the GCRS; the series'
// FK5-based J2000 frames differ from it by the 0.02 arcsec frame bias, which the NPB matrix takes out.
#include "ephemeris/vec3.h"

namespace skyig::ephemeris {

struct Nutation {
  double dpsi = 0.0;  // nutation in longitude, radians
  double deps = 0.0;  // nutation in obliquity, radians
};

// IAU 2000B nutation at TT Julian date jdTt.
Nutation nutation2000B(double jdTt);

// Mean obliquity of the ecliptic, IAU 2006 (radians).
double meanObliquity2006(double jdTt);

// Earth rotation angle (IAU 2000), radians in [0, 2 pi).
double earthRotationAngle(double jdUt1);

struct EarthOrientation {
  double gmst = 0.0;       // Greenwich mean sidereal time, radians [0, 2 pi)
  double gast = 0.0;       // Greenwich apparent sidereal time, radians [0, 2 pi)
  double epsA = 0.0;       // mean obliquity of date
  Nutation nutation;
  Mat3 npb;                // GCRS (J2000) -> true equator and equinox of date
};

// Everything at once (the nutation series is evaluated once).
EarthOrientation earthOrientation(double jdTt, double jdUt1);
// The same with a nutation computed elsewhere (interpolated by EphemerisCache).
EarthOrientation earthOrientation(double jdTt, double jdUt1, const Nutation& nutation);

// Fukushima-Williams bias-precession angles (IAU 2006), radians: gamma-bar, phi-bar, psi-bar.
void precessionAngles2006(double jdTt, double& gamb, double& phib, double& psib);

}  // namespace skyig::ephemeris
