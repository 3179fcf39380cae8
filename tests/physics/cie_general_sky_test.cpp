// The CIE standard general sky (Wang, Ji & Zhang 2011, eq. 6-7, corrected: the last term of
// eq. 6 is E cos^2(gamma), and eq. 7 divides by F(0, theta_s)) against values computed by hand
// from the standard's formula (CIE S 011/E:2003 = ISO 15469:2004; Darula & Kittler 2002) and
// its defining properties.
#include "physics/analytic/analytic_sky.h"
#include "physics/analytic/cie_sky_types.h"
#include "physics/physics.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig;
using sky::cieSkyType;

namespace {
using skyig::kDeg;

shader::CieSkyCoefficients coefficients(int type) {
  const auto& t = cieSkyType(type);
  return {t.a, t.b, t.c, t.d, t.e};
}

// Relative luminance of the sky element at view zenith angle z and azimuth relative to the sun.
double relative(int type, double sunZenithDeg, double zenithDeg, double relAzimuthDeg) {
  const double zs = sunZenithDeg * kDeg, z = zenithDeg * kDeg, az = relAzimuthDeg * kDeg;
  const double cosChi = std::cos(zs) * std::cos(z) + std::sin(zs) * std::sin(z) * std::cos(az);
  return shader::cieRelativeLuminance(coefficients(type), std::cos(z), std::acos(cosChi), zs);
}
}  // namespace

// Worked values of type 12 at sun zenith 30 and 60 deg, towards (azimuth 0) and away from the
// sun (180), view zenith angles 30/60/80/85/89.
TEST(CieGeneralSky, Type12WorkedValues) {
  const double zeniths[5] = {30, 60, 80, 85, 89};
  const double towards30[5] = {3.852, 1.726, 1.687, 1.733, 1.630};
  const double away30[5] = {0.493, 0.519, 0.919, 1.086, 1.137};
  const double towards60[5] = {2.579, 13.479, 10.175, 9.738, 8.647};
  const double away60[5] = {0.775, 1.236, 2.494, 2.977, 3.125};
  for (int i = 0; i < 5; ++i) {
    EXPECT_NEAR(relative(12, 30, zeniths[i], 0), towards30[i], 2e-3) << zeniths[i];
    EXPECT_NEAR(relative(12, 30, zeniths[i], 180), away30[i], 2e-3) << zeniths[i];
    EXPECT_NEAR(relative(12, 60, zeniths[i], 0), towards60[i], 2e-3) << zeniths[i];
    EXPECT_NEAR(relative(12, 60, zeniths[i], 180), away60[i], 2e-3) << zeniths[i];
  }
}

// Type 1, the standard overcast sky, has phi(0)/phi(90) = 1 + 4 exp(-0.7) = 2.986: the zenith
// is about three times the horizon, whatever the sun does.
TEST(CieGeneralSky, OvercastZenithThreeTimesHorizon) {
  for (double sunZenith : {10.0, 45.0, 80.0})
    for (double az : {0.0, 90.0, 180.0})
      EXPECT_NEAR(1.0 / relative(1, sunZenith, 90.0, az), 1.0 + 4.0 * std::exp(-0.7), 1e-3);
}

// Type 5 is uniform.
TEST(CieGeneralSky, Type5Uniform) {
  for (double z : {0.0, 40.0, 89.0})
    for (double az : {0.0, 120.0}) EXPECT_NEAR(relative(5, 50.0, z, az), 1.0, 1e-12);
}

// The clear sky (type 12) is brightest next to the sun and darkest roughly 90 deg from it.
TEST(CieGeneralSky, ClearSkyBrightestNearSunDarkestNinetyAway) {
  const double sunZenith = 50.0;
  double minValue = 1e9, minDistance = 0.0, maxValue = 0.0, maxDistance = 180.0;
  for (double z = 0.5; z < 90.0; z += 0.5)
    for (double az = 0.0; az <= 180.0; az += 1.0) {
      const double v = relative(12, sunZenith, z, az);
      const double cosChi = std::cos(sunZenith * kDeg) * std::cos(z * kDeg) +
                            std::sin(sunZenith * kDeg) * std::sin(z * kDeg) * std::cos(az * kDeg);
      const double chi = std::acos(cosChi) / kDeg;
      if (v < minValue) minValue = v, minDistance = chi;
      if (v > maxValue) maxValue = v, maxDistance = chi;
    }
  EXPECT_LT(maxDistance, 1.0);
  EXPECT_NEAR(minDistance, 90.0, 15.0);
  EXPECT_GT(maxValue / minValue, 10.0);
}

// The analytic sky writes the CIE indicatrix in Perez form with a constant K = 1 - c exp(d pi/2)
// (physics/analytic/analytic_sky.glsl); its luminance must equal the CIE formula for every type.
TEST(CieGeneralSky, AnalyticSkyLuminanceEqualsCieFormula) {
  for (int type = 1; type <= 15; ++type) {
    sky::SkyConditions c;
    c.model = sky::SkyModel::Cie;
    c.cieType = type;
    const double sunAltitude = 35.0 * kDeg;
    const auto sky = sky::makeAnalyticSky(c, 0.0, sunAltitude);
    const double zenith = shader::rec709Luminance(sky::analyticSkyLightOnly(sky.params, {0, 0, 1}));
    for (double z : {20.0, 60.0, 85.0})
      for (double az : {30.0, 150.0}) {
        const glm::dvec3 dir = sky::enuDirection(az * kDeg, (90.0 - z) * kDeg);
        const double l = shader::rec709Luminance(sky::analyticSkyLightOnly(sky.params, dir));
        EXPECT_NEAR(l / zenith, relative(type, 55.0, z, az), 2e-6 * relative(type, 55.0, z, az) + 1e-9)
            << "type " << type << " z " << z << " az " << az;
      }
  }
}

TEST(CieGeneralSky, RejectsUnknownType) {
  EXPECT_THROW(cieSkyType(0), std::out_of_range);
  EXPECT_THROW(cieSkyType(16), std::out_of_range);
}
