#pragma once
// The expensive part of an ephemeris update: the VSOP87B, ELP 2000-82B and nutation series at
// one instant. Everything else (observer, rotations, aberration, refraction, appearance) is cheap
// and is assembled from this state; EphemerisCache interpolates it between hourly nodes.
#include <array>

#include "ephemeris/earth_orientation.h"
#include "ephemeris/vsop87.h"

namespace skyig::ephemeris {

struct SeriesState {
  double jdTt = 0.0;
  StateVector earth;                    // heliocentric, J2000 equatorial, au and au/day
  std::array<StateVector, 5> planets;   // Mercury, Venus, Mars, Jupiter, Saturn, same frame
  Vec3 moonGeocentricKm;                // J2000 equatorial, at jdTt minus the mean light time
  Nutation nutation;                    // IAU 2000B
};

// Mean light time from the moon (384400 km), days.
inline constexpr double kMoonLightTimeDays = 384400.0 / kLightKmPerS / 86400.0;

// Evaluates every series at TT Julian date jdTt.
SeriesState evaluateSeries(double jdTt);

}  // namespace skyig::ephemeris
