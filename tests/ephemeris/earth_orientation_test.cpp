// Earth orientation against the SOFA/ERFA documented test values (t_sofa_c.c / t_erfa_c.c, which
// the IAU SOFA documentation quotes) and Meeus' worked examples.
#include "ephemeris/earth_orientation.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace skyig::ephemeris;

namespace {
constexpr double kMjd0 = 2400000.5;
double hmsToSeconds(int h, int m, double s) { return h * 3600.0 + m * 60.0 + s; }
double radToSecondsOfTime(double a) { return a / kTwoPi * 86400.0; }
}  // namespace

TEST(EarthOrientation, Nutation2000BMatchesSofa) {
  const Nutation n = nutation2000B(kMjd0 + 53736.0);
  EXPECT_NEAR(n.dpsi, -0.9632552291148362783e-5, 1e-13);
  EXPECT_NEAR(n.deps, 0.4063197106621159367e-4, 1e-13);
}

TEST(EarthOrientation, PrecessionAnglesMatchSofaPfw06) {
  double gamb = 0, phib = 0, psib = 0;
  precessionAngles2006(kMjd0 + 50123.9999, gamb, phib, psib);
  EXPECT_NEAR(gamb, -0.2243387670997995690e-5, 1e-15);
  EXPECT_NEAR(phib, 0.4091014602391312808, 1e-12);
  EXPECT_NEAR(psib, -0.9501954178013031895e-3, 1e-14);
  EXPECT_NEAR(meanObliquity2006(kMjd0 + 50123.9999), 0.4091014316587367491, 1e-12);
  EXPECT_NEAR(meanObliquity2006(kMjd0 + 54388.0), 0.4090749229387258204, 1e-14);
}

TEST(EarthOrientation, EraAndSiderealTimeMatchSofa) {
  EXPECT_NEAR(earthRotationAngle(kMjd0 + 54388.0), 0.4022837240028158102, 1e-12);
  const EarthOrientation eo = earthOrientation(kMjd0 + 53736.0, kMjd0 + 53736.0);
  EXPECT_NEAR(eo.gmst, 1.754174971870091203, 1e-12);  // eraGmst06
  // eraGst06a uses IAU 2000A nutation; 2000B differs by under 1 mas (5e-9 rad).
  EXPECT_NEAR(eo.gast, 1.754166137675019159, 1e-8);
}

TEST(EarthOrientation, NpbMatrixMatchesSofaPnm06a) {
  const EarthOrientation eo = earthOrientation(kMjd0 + 50123.9999, kMjd0 + 50123.9999);
  const double expected[9] = {0.9999995832794205484,  0.8372382772630962111e-3, 0.3639684771140623099e-3,
                              -0.8372533744743683605e-3, 0.9999996486492861646, 0.4132905944611019498e-4,
                              -0.3639337469629464969e-3, -0.4163377605910663999e-4, 0.9999999329094260057};
  for (int i = 0; i < 9; ++i) EXPECT_NEAR(eo.npb.m[static_cast<std::size_t>(i)], expected[i], 1e-8) << i;
}

TEST(EarthOrientation, MeeusExample12aSiderealTime) {
  // 1987 April 10, 0h UT: mean 13h10m46.3668s, apparent 13h10m46.1351s (Meeus ex. 12.a, 12.b
  // context); 19h21m00s UT: mean 8h34m57.0896s (ex. 12.b). TT = UT + 55.3 s (delta T 1987).
  const double jd = 2446895.5;
  const EarthOrientation eo = earthOrientation(jd + 55.3 / 86400.0, jd);
  EXPECT_NEAR(radToSecondsOfTime(eo.gmst), hmsToSeconds(13, 10, 46.3668), 0.005);
  EXPECT_NEAR(radToSecondsOfTime(eo.gast), hmsToSeconds(13, 10, 46.1351), 0.005);
  const double jd2 = jd + hmsToSeconds(19, 21, 0.0) / 86400.0;
  const EarthOrientation eo2 = earthOrientation(jd2 + 55.3 / 86400.0, jd2);
  EXPECT_NEAR(radToSecondsOfTime(eo2.gmst), hmsToSeconds(8, 34, 57.0896), 0.005);
}

TEST(EarthOrientation, MeeusExample22aNutation) {
  // 1987 April 10, 0h TD: dpsi = -3.788", deps = +9.443", eps0 = 23 26' 27.407" (IAU 1980);
  // IAU 2006 has eps0 0.042" smaller, and 2000B nutation differs from 1980 by ~0.02".
  const double jd = 2446895.5;
  const Nutation n = nutation2000B(jd);
  EXPECT_NEAR(n.dpsi / kArcsecToRad, -3.788, 0.05);
  EXPECT_NEAR(n.deps / kArcsecToRad, 9.443, 0.05);
  EXPECT_NEAR(meanObliquity2006(jd) / kArcsecToRad, 23 * 3600 + 26 * 60 + 27.407 - 0.042, 0.01);
}

TEST(EarthOrientation, NpbIsARotation) {
  const EarthOrientation eo = earthOrientation(2469807.5, 2469807.5);  // 2050
  const Mat3 p = eo.npb * transposed(eo.npb);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(p.m[static_cast<std::size_t>(3 * i + j)], i == j ? 1.0 : 0.0, 1e-15);
}
