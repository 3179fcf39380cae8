#pragma once
// VSOP87B planetary theory (Bretagnon & Francou 1988, A&A 202, 309): heliocentric ecliptic
// spherical coordinates referred to the dynamical ecliptic and equinox J2000, truncated for
// 1900-2100 (ephemeris/data/vsop87b_truncated.inc; ephemeris/data/README.md gives the thresholds
// and the error each adds: at most 0.04 arcsec for the sun, 0.3-0.8 arcsec for the planets).
#include "ephemeris/vec3.h"

namespace skyig::ephemeris {

enum class VsopBody { Earth, Mercury, Venus, Mars, Jupiter, Saturn };

struct StateVector {
  Vec3 position;  // au
  Vec3 velocity;  // au per day
};

// Heliocentric position and velocity, rectangular, equatorial J2000 (FK5 axes through the
// VSOP87 frame rotation given with the theory), at TDB Julian date jdTdb.
StateVector vsop87Heliocentric(VsopBody body, double jdTdb);

// Rotation from the VSOP87/ELP dynamical ecliptic J2000 to the FK5 equator J2000 (VSOP87 notice).
const Mat3& vsopEclipticToFk5();

}  // namespace skyig::ephemeris
