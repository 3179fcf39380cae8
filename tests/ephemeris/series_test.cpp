// The series machinery: the polynomial sine/cosine and a VSOP87 check value.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "ephemeris/fast_sincos.h"
#include "ephemeris/vsop87.h"

using namespace skyig::ephemeris;

TEST(Series, FastSinCosMatchesTheLibrary) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> wide(-2e5, 2e5), narrow(-7.0, 7.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = i % 2 ? wide(rng) : narrow(rng);
    double s = 0.0, c = 0.0;
    fastSinCos(x, s, c);
    worst = std::max({worst, std::fabs(s - std::sin(x)), std::fabs(c - std::cos(x))});
  }
  EXPECT_LT(worst, 1e-15);
  double s = 1.0, c = 0.0;
  fastSinCos(0.0, s, c);
  EXPECT_EQ(s, 0.0);
  EXPECT_EQ(c, 1.0);
}

TEST(Series, Vsop87bEarthCheckValueAtJ2000) {
  // VSOP87 distribution, file vsop87.chk, VSOP87B EARTH at JD 2451545.0:
  // L = 1.7519238681 rad, B = -0.0000039656 rad, R = 0.9833276819 au. The truncated series
  // may differ by its bound (< 0.04 arcsec = 2e-7 rad).
  const StateVector s = vsop87Heliocentric(VsopBody::Earth, 2451545.0);
  const Vec3 e = transposed(vsopEclipticToFk5()) * s.position;
  const double r = norm(e);
  EXPECT_NEAR(wrapTwoPi(std::atan2(e.y, e.x)), 1.7519238681, 1e-7);
  EXPECT_NEAR(std::asin(e.z / r), -0.0000039656, 1e-8);
  EXPECT_NEAR(r, 0.9833276819, 1e-7);
  // The earth moves about 2 pi au a year: the velocity is 0.0172 au/day, tangential.
  EXPECT_NEAR(norm(s.velocity), 0.01720, 0.0003);
  EXPECT_LT(std::fabs(dot(s.velocity, s.position)) / (norm(s.velocity) * r), 0.02);
}
