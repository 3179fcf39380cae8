// Apparent geocentric places against Meeus, Astronomical Algorithms (2nd ed., 1998) examples.
#include <gtest/gtest.h>

#include <cmath>

#include "ephemeris/ephemeris.h"

using namespace skyig::ephemeris;

namespace {
double hms(int h, int m, double s) { return (h + m / 60.0 + s / 3600.0) * 15.0 * kDegToRad; }
double dms(int sign, int d, int m, double s) { return sign * (d + m / 60.0 + s / 3600.0) * kDegToRad; }
double separationArcsec(double ra1, double de1, double ra2, double de2) {
  const Vec3 a{std::cos(de1) * std::cos(ra1), std::cos(de1) * std::sin(ra1), std::sin(de1)};
  const Vec3 b{std::cos(de2) * std::cos(ra2), std::cos(de2) * std::sin(ra2), std::sin(de2)};
  return angleBetween(a, b) / kArcsecToRad;
}
}  // namespace

TEST(WorkedExamples, SunMeeus25b) {
  // 1992 October 13.0 TD, complete VSOP87: alpha 13h13m30.749s, delta -7 47' 01.74".
  const ApparentPlace p = apparentGeocentricPlace(Body::Sun, 2448908.5);
  EXPECT_LT(separationArcsec(p.rightAscensionRad, p.declinationRad, hms(13, 13, 30.749), dms(-1, 7, 47, 1.74)), 1.0);
  EXPECT_NEAR(p.distanceKm / kAuKm, 0.99761, 1e-5);  // R = 0.99761 au, ex. 25.a/25.b
}

TEST(WorkedExamples, VenusMeeus33a) {
  // 1992 December 20, 0h TD, complete VSOP87: alpha 21h04m41.454s, delta -18 53' 16.84".
  const ApparentPlace p = apparentGeocentricPlace(Body::Venus, 2448976.5);
  EXPECT_LT(separationArcsec(p.rightAscensionRad, p.declinationRad, hms(21, 4, 41.454), dms(-1, 18, 53, 16.84)), 1.0);
}

TEST(WorkedExamples, MoonMeeus47a) {
  // 1992 April 12, 0h TD: alpha 134.688470, delta +13.768368 deg, distance 368409.7 km, from
  // Meeus' abridged ELP-2000/82 (errors up to 10" in longitude, 4" in latitude).
  const ApparentPlace p = apparentGeocentricPlace(Body::Moon, 2448724.5);
  EXPECT_LT(separationArcsec(p.rightAscensionRad, p.declinationRad, 134.688470 * kDegToRad, 13.768368 * kDegToRad),
            12.0);
  EXPECT_NEAR(p.distanceKm, 368409.7, 10.0);
}

TEST(WorkedExamples, MoonPhaseMeeus48a) {
  // 1992 April 12, 0h TD: phase angle i = 69.0756 deg, illuminated fraction k = 0.6786,
  // position angle of the bright limb chi = 285.0 deg.
  const ApparentPlace p = apparentGeocentricPlace(Body::Moon, 2448724.5);
  EXPECT_NEAR(p.phaseAngleRad / kDegToRad, 69.0756, 0.05);
  EXPECT_NEAR(0.5 * (1.0 + std::cos(p.phaseAngleRad)), 0.6786, 0.001);
  EXPECT_NEAR(p.brightLimbPositionAngleRad / kDegToRad, 285.0, 0.2);
}
