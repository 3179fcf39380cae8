#pragma once
// Shared by the star tests: the real catalogue and stars placed at chosen horizon coordinates.
#include "ephemeris/ephemeris.h"
#include "ephemeris/bsc5.h"
#include "physics/stars/star_catalogue.h"

#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>
#include "physics/common/units.h"

namespace skyig::night_testing {

using skyig::kDeg;

inline std::string cataloguePath() { return std::string(SKYIG_SOURCE_DIR) + "/ephemeris/data/bsc5.csv"; }

inline const std::vector<ephemeris::Star>& catalogue() {
  static const std::vector<ephemeris::Star> stars = ephemeris::loadStarCatalogue(cataloguePath());
  return stars;
}

// A star of magnitude `vmag` seen (airless) at azimuth/altitude in degrees from `sky`'s
// observer: the J2000 direction is the inverse of the ephemeris' rotation (aberration, 20",
// neglected).
inline ephemeris::Star starAt(const ephemeris::SkyEphemeris& sky, double azimuthDeg, double altitudeDeg, double vmag,
                              double bMinusV, int hr = 1) {
  const double az = azimuthDeg * kDeg, alt = altitudeDeg * kDeg;
  const ephemeris::Vec3 enu{std::sin(az) * std::cos(alt), std::cos(az) * std::cos(alt), std::sin(alt)};
  const ephemeris::Vec3 u = ephemeris::transposed(sky.j2000ToEnu) * enu;
  ephemeris::Star s;
  s.hr = hr;
  s.raRad = std::atan2(u.y, u.x);
  s.decRad = std::asin(u.z);
  s.vmag = vmag;
  s.bMinusV = bMinusV;
  s.directionJ2000 = u;
  return s;
}

}  // namespace skyig::night_testing
