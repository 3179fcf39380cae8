#pragma once
// Lunar theory ELP 2000-82B (Chapront-Touze & Chapront 1983, A&A 124, 50; 1988, A&A 190, 342),
// all 36 series truncated for 1900-2100 (ephemeris/data/elp82b_truncated.inc: 934 of 37872
// terms, adding at most 0.22 arcsec in longitude, 0.17 arcsec in latitude and 0.7 km in distance).
#include "ephemeris/vec3.h"

namespace skyig::ephemeris {

// Geocentric position of the moon, km, rectangular, equatorial J2000 (FK5 axes), at TDB Julian
// date jdTdb. The theory's mean ecliptic of date is taken to J2000 with Laskar's precession
// (ELP 2000-82B notice) and then to the equator with the VSOP87 frame rotation.
Vec3 elp82bGeocentric(double jdTdb);

}  // namespace skyig::ephemeris
