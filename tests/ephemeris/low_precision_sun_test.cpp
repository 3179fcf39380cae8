#include "ephemeris/low_precision_sun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig::ephemeris;

namespace {
constexpr double kDeg = std::numbers::pi / 180.0;
}

// Meeus example 25.a: 1992 October 13.0 TD (JD 2448908.5): apparent
// alpha = 13h13m31.4s = 198.38083 deg, delta = -7 deg 47' 06" = -7.78507 deg, R = 0.99766 AU.
TEST(LowPrecisionSun, MeeusExample25a) {
  const EquatorialPosition p = lowPrecisionSunEquatorial(2448908.5);
  EXPECT_NEAR(p.rightAscension / kDeg, 198.38083, 2e-4);
  EXPECT_NEAR(p.declination / kDeg, -7.78507, 2e-4);
  EXPECT_NEAR(p.distanceAu, 0.99766, 1e-5);
}

// Meeus example 12.a: 1987 April 10, 0h UT, mean sidereal time 13h10m46.3668s.
TEST(SiderealTime, MeeusExample12a) {
  const double gmst = greenwichMeanSiderealTime(2446895.5);
  EXPECT_NEAR(gmst / kDeg, (13.0 + 10.0 / 60.0 + 46.3668 / 3600.0) * 15.0, 1e-6);
}

// At an equinox the sun culminates at altitude 90 - latitude, due south in the north.
TEST(LowPrecisionSun, EquinoxNoonAtGreenwich) {
  // 2026 March 20 14:46 UTC is the equinox; local apparent noon at Greenwich is ~12:07:30 UTC.
  const HorizontalPosition h = lowPrecisionSunHorizontal({2026, 3, 20, 12 * 3600.0 + 7.5 * 60.0},
                                                         51.4779 * kDeg, 0.0);
  EXPECT_NEAR(h.altitude / kDeg, 90.0 - 51.4779, 0.1);
  EXPECT_NEAR(h.azimuth / kDeg, 180.0, 0.5);
}

// The sun rises in the east: at 06:00 local solar time on the equator at an equinox it is on
// the horizon due east.
TEST(LowPrecisionSun, EquinoxSunriseOnEquatorIsEast) {
  const HorizontalPosition h = lowPrecisionSunHorizontal({2026, 3, 20, 6 * 3600.0 + 7.5 * 60.0}, 0.0, 0.0);
  EXPECT_NEAR(h.altitude / kDeg, 0.0, 0.3);
  EXPECT_NEAR(h.azimuth / kDeg, 90.0, 0.3);
}
