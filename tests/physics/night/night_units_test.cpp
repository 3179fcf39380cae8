// Surface-brightness units of the night sky (physics/night/units.glsl): closed forms and the
// published anchors they come from.
#include "physics/night/diffuse_physics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig::shader;

namespace {
constexpr double kArcsecondSr = (std::numbers::pi / (180.0 * 3600.0)) * (std::numbers::pi / (180.0 * 3600.0));
}

// 0 mag/arcsec^2: a V = 0 star (2.54e-6 lx, Allen's Astrophysical Quantities) per square arcsecond.
TEST(NightUnits, ZeroPointIsAVZeroStarPerSquareArcsecond) {
  EXPECT_NEAR(magArcsec2ToCdM2(0.0), 2.54e-6 / kArcsecondSr, 0.01 * magArcsec2ToCdM2(0.0));
}

TEST(NightUnits, DarkSkyMagnitudesInCandelas) {
  EXPECT_NEAR(magArcsec2ToCdM2(22.0), 1.71e-4, 0.01e-4);
  EXPECT_NEAR(magArcsec2ToCdM2(21.5), 2.71e-4, 0.01e-4);
  for (double m : {16.0, 21.7, 25.0}) EXPECT_NEAR(cdM2ToMagArcsec2(magArcsec2ToCdM2(m)), m, 1e-9);
}

// 1 S10 = a V = 10 star per square degree = 27.78 mag/arcsec^2.
TEST(NightUnits, S10IsATenthMagnitudeStarPerSquareDegree) {
  EXPECT_NEAR(s10ToMagArcsec2(1.0), 10.0 + 2.5 * std::log10(3600.0 * 3600.0), 1e-9);
  EXPECT_NEAR(s10ToMagArcsec2(1.0), 27.78, 0.005);
  EXPECT_NEAR(s10ToCdM2(1.0), magArcsec2ToCdM2(10.0) / (3600.0 * 3600.0), 1e-18);
  // The dark zenith of Roach & Gordon's budget: ~220 S10 = 21.9 mag/arcsec^2.
  EXPECT_NEAR(s10ToMagArcsec2(220.0), 21.9, 0.05);
}

// Leinert et al. (1998): table 17's 77 units at the ecliptic pole are the pole's 60 S10.
TEST(NightUnits, LeinertTableUnitsToS10) { EXPECT_NEAR(leinertToS10(77.0), 60.0, 1.0); }
