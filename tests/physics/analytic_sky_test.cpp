// The analytic sky's absolute levels and the lighting derived from it, against reference
// values (Bruneton's 2017 clear atmosphere, Preetham et al. 1999) and closed forms.
#include "physics/analytic/analytic_sky.h"
#include "sky/sky_state.h"
#include "physics/physics.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig;
using namespace skyig::sky;

namespace {
using skyig::kDeg;
double lum(const glm::dvec3& rgb) { return shader::rec709Luminance(rgb); }
}  // namespace

// Sun at the zenith in a clear atmosphere: ~115 klx direct and ~8 klx from the sky on a
// horizontal surface (Bruneton's 2017 very clean default atmosphere). The direct beam
// must land near it; Preetham's sky is known to be bright at high sun (Zotti et al. 2007) and
// gives ~27 klx of diffuse light, within the range measured under clear skies with some haze
// (10-30 klx), so only that range is asserted.
TEST(AnalyticSky, ZenithSunIlluminanceNearClearAtmosphereReference) {
  SkyConditions c;
  c.turbidity = 2.0;
  const AnalyticSkyState s = makeAnalyticSky(c, 0.0, 90.0 * kDeg);
  EXPECT_NEAR(lum(s.lighting.directHorizontal), 115000.0, 0.15 * 115000.0);
  EXPECT_GT(lum(s.lighting.diffuseHorizontal), 8000.0);
  EXPECT_LT(lum(s.lighting.diffuseHorizontal), 30000.0);
}

// Preetham's zenith luminance at sun zenith 30 deg, T = 2 (by hand from appendix A.2:
// chi = (4/9 - 2/120)(pi - pi/3) = 0.89594, Y_z = (4.0453*2 - 4.9710) tan(chi) - 0.431 + 2.4192
// = 3.1196 * 1.24967 - 0.431 + 2.4192 = 5.8867 kcd/m^2).
TEST(AnalyticSky, PreethamZenithLuminanceHandValue) {
  EXPECT_NEAR(shader::preethamZenithLuminance(2.0, 30.0 * kDeg), 5886.7, 0.5);
  SkyConditions c;
  c.turbidity = 2.0;
  const AnalyticSkyState s = makeAnalyticSky(c, 0.0, 60.0 * kDeg);
  EXPECT_NEAR(lum(analyticSkyLightOnly(s.params, {0, 0, 1})), 5886.7, 0.01 * 5886.7);
}

// A Lambertian ground reflects albedo/pi of the horizontal illuminance.
TEST(AnalyticSky, GroundIsLambertianUnderSunAndSky) {
  SkyConditions c;
  c.groundAlbedo = 0.3;
  const AnalyticSkyState s = makeAnalyticSky(c, 1.0, 40.0 * kDeg);
  const glm::dvec3 e = s.lighting.directHorizontal + s.lighting.diffuseHorizontal;
  const glm::dvec3 ground = analyticSkyRadiance(s.params, glm::normalize(glm::dvec3(0.3, 0.2, -0.5)));
  EXPECT_NEAR(lum(ground), 0.3 * lum(e) / std::numbers::pi, 1e-9 * lum(e));
}

// For the uniform sky (CIE type 5) the sky illuminance is pi times the luminance, exactly.
TEST(AnalyticSky, UniformSkyIlluminanceIsPiTimesLuminance) {
  SkyConditions c;
  c.model = SkyModel::Cie;
  c.cieType = 5;
  const AnalyticSkyState s = makeAnalyticSky(c, 0.0, 30.0 * kDeg);
  const double l = lum(analyticSkyLightOnly(s.params, {0, 0, 1}));
  EXPECT_NEAR(lum(s.lighting.diffuseHorizontal), std::numbers::pi * l, 1e-6 * l);
  EXPECT_NEAR(s.lighting.meanSkyLuminance, l, 1e-9 * l);
  EXPECT_EQ(lum(s.lighting.directHorizontal), 0.0);  // overcast: no sun disc
}

// The overcast zenith follows Krochmann & Seidl: 123 + 8600 sin(h) cd/m^2, and is grey (D65).
TEST(AnalyticSky, OvercastZenithLuminanceAndColour) {
  SkyConditions c;
  c.model = SkyModel::Cie;
  c.cieType = 1;
  const AnalyticSkyState s = makeAnalyticSky(c, 0.0, 30.0 * kDeg);
  const glm::dvec3 z = analyticSkyLightOnly(s.params, {0, 0, 1});
  EXPECT_NEAR(lum(z), 123.0 + 8600.0 * 0.5, 1e-6 * lum(z));
  EXPECT_NEAR(z.r / z.b, 1.0, 1e-3);
  EXPECT_NEAR(z.g / z.b, 1.0, 1e-3);
}

// The solar disc carries the direct illuminance: radiance times its solid angle.
TEST(AnalyticSky, SunDiscRadianceTimesSolidAngleIsDirectNormalIlluminance) {
  const AnalyticSkyState s = makeAnalyticSky(SkyConditions{}, 0.5, 50.0 * kDeg);
  const double omega = 2.0 * std::numbers::pi * (1.0 - s.params.cosSunRadius);
  EXPECT_NEAR(lum(analyticSunDiscOnly(s.params, s.params.sunDirection)) * omega * std::sin(50.0 * kDeg),
              lum(s.lighting.directHorizontal), 1e-6 * lum(s.lighting.directHorizontal));
  // The disc outside the atmosphere is ~1.9e9 cd/m^2; through the air it is dimmer but close.
  EXPECT_GT(lum(s.params.sunRadiance), 1.0e9);
  EXPECT_LT(lum(s.params.sunRadiance), 1.9e9);
}

// Twilight dims the sky by orders of magnitude, continuously from sunset; at -18 deg the
// sun's light is down to the level of a moonless night sky (~1e-4 cd/m^2).
TEST(AnalyticSky, TwilightFallsContinuously) {
  double previous = 1e30;
  for (double h = 2.0; h >= -18.0; h -= 1.0) {
    const AnalyticSkyState s = makeAnalyticSky(SkyConditions{}, 0.0, h * kDeg);
    const double zenith = lum(analyticSkyLightOnly(s.params, {0, 0, 1}));
    EXPECT_LT(zenith, previous) << h;
    EXPECT_TRUE(std::isfinite(zenith));
    previous = zenith;
  }
  EXPECT_LT(previous, 2e-4);
}

TEST(SkyState, RejectsBadInput) {
  ObserverState o;
  o.latitudeDeg = 91.0;
  EXPECT_THROW(buildSkyState(o, SkyConditions{}), std::invalid_argument);
  o = ObserverState{};
  o.longitudeDeg = std::nan("");
  EXPECT_THROW(buildSkyState(o, SkyConditions{}), std::invalid_argument);
  o = ObserverState{};
  o.utc.day = 31;
  o.utc.month = 6;
  EXPECT_THROW(buildSkyState(o, SkyConditions{}), std::invalid_argument);
  SkyConditions c;
  c.turbidity = 0.5;
  EXPECT_THROW(buildSkyState(ObserverState{}, c), std::invalid_argument);
  try {
    ObserverState bad;
    bad.latitudeDeg = 123.0;
    buildSkyState(bad, SkyConditions{});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("latitude 123"), std::string::npos) << e.what();
  }
}

// Every state carries the extinction towards space at the observer's altitude, shared between
// the states of one builder's caches at nearly the same altitude (the nearest point of a 25 m
// grid, 2 % above 1250 m) and rebuilt after a climb; another builder's caches are its own (no
// process-wide state), and what a state gets does not depend on what its builder built before:
// a builder that came down from 3 km gives the profile of a fresh one.
TEST(SkyState, ExtinctionProfileFollowsTheAltitude) {
  ObserverState o;
  o.heightM = 581.0;
  SkyStateCaches caches, others;
  const SkyState a = buildSkyState(o, SkyConditions{}, std::nullopt, &caches);
  o.heightM += 5.0;  // 581 and 586 m: both nearest to 575 m
  const SkyState b = buildSkyState(o, SkyConditions{}, std::nullopt, &caches);
  ASSERT_TRUE(a.extinction && b.extinction);
  EXPECT_EQ(a.extinction, b.extinction);
  EXPECT_EQ(a.extinction->altitudeM(), 575.0);
  EXPECT_NE(buildSkyState(o, SkyConditions{}, std::nullopt, &others).extinction, a.extinction);
  o.heightM = 3000.0;  // 1250 m * 1.02^44 = 2995.6 m
  const SkyState c = buildSkyState(o, SkyConditions{}, std::nullopt, &caches);
  EXPECT_NE(c.extinction, a.extinction);
  EXPECT_NEAR(c.extinction->altitudeM(), 1250.0 * std::pow(1.02, 44), 1e-9);
  EXPECT_GT(c.extinction->rec709(std::numbers::pi / 2).g, a.extinction->rec709(std::numbers::pi / 2).g);
  // Down again, to a height between two grid points the first builder never used (597 m: 600).
  o.heightM = 597.0;
  SkyStateCaches fresh;
  const SkyState afterClimb = buildSkyState(o, SkyConditions{}, std::nullopt, &caches);
  const SkyState first = buildSkyState(o, SkyConditions{}, std::nullopt, &fresh);
  EXPECT_EQ(afterClimb.extinction->altitudeM(), 600.0);
  EXPECT_EQ(afterClimb.extinction->rec709(0.1).r, first.extinction->rec709(0.1).r);
  EXPECT_EQ(afterClimb.sceneLuminance, first.sceneLuminance);
}

// The default state is the sun of the ephemeris: midsummer evening at Innsbruck, the sun in
// the west-north-west about 20 deg up, and the eye adapted to a bright sky.
TEST(SkyState, DefaultStateUsesTheEphemeris) {
  const SkyState s = buildSkyState(ObserverState{}, SkyConditions{});
  EXPECT_NEAR(s.sunAzimuth / kDeg, 283.6, 1.0);
  EXPECT_NEAR(s.sunAltitude / kDeg, 19.7, 1.0);
  EXPECT_GT(s.worldAdaptationLuminance, 1000.0);
}

// The air at the observer refracts what is seen (Saemundsson, scaled by Meeus' P/T factor): a
// cold high-pressure air mass lifts the setting sun by the ratio of the two scales, and the one
// default is the ICAO standard atmosphere.
TEST(SkyState, RefractionUsesTheObserversPressureAndTemperature) {
  ObserverState o;
  EXPECT_EQ(o.pressureHpa, 1013.25);
  EXPECT_EQ(o.temperatureC, 15.0);
  o.utc = {2026, 6, 21, 19 * 3600.0 + 20 * 60.0};  // Innsbruck, the sun about a degree up
  const SkyState standard = buildSkyState(o, SkyConditions{});
  ObserverState cold = o;
  cold.pressureHpa = 1040.0;
  cold.temperatureC = -12.0;
  const SkyState dense = buildSkyState(cold, SkyConditions{});
  const double liftStandard = standard.sunApparentAltitude - standard.sunAltitude;
  const double liftDense = dense.sunApparentAltitude - dense.sunAltitude;
  ASSERT_GT(liftStandard, 0.0);
  EXPECT_NEAR(liftDense / liftStandard,
              skyig::ephemeris::refractionScale(1040.0, -12.0) / skyig::ephemeris::refractionScale(1013.25, 15.0), 1e-9);
  EXPECT_NEAR(liftDense / liftStandard, (1040.0 / 1013.25) * (288.0 / 261.0), 1e-9);
  cold.pressureHpa = std::nan("");
  EXPECT_THROW(buildSkyState(cold, SkyConditions{}), std::invalid_argument);
}
