// Zodiacal light (Leinert et al. 1998 table 17) and airglow (van Rhijn) on the CPU.
#include "physics/night/diffuse_physics.h"
#include "physics/physics.h"
#include "physics/night/night_diffuse.h"
#include "physics/night/zodiacal_light.h"
#include "sky/sky_state.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig;
using namespace skyig::sky;
using namespace skyig::sky::night;

namespace {

using skyig::kDeg;

double y709(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

glm::dvec3 view(double azimuthDeg, double altitudeDeg) { return enuDirection(azimuthDeg * kDeg, altitudeDeg * kDeg); }

// The first minute of a spring evening (mid-northern latitude, the ecliptic steep in the west)
// with the sun at least 18 deg down: astronomical dusk is over.
SkyState afterDusk() {
  ObserverState o;
  o.latitudeDeg = 40.0;
  o.longitudeDeg = 0.0;
  o.heightM = 1500.0;
  for (double minutes = 17 * 60; minutes < 23 * 60; minutes += 2) {
    o.utc = {2026, 3, 20, minutes * 60.0};
    SkyState s = buildSkyState(o, SkyConditions{});
    if (s.sunAltitude < -18.0 * kDeg) return s;
  }
  throw std::runtime_error("no dusk found");
}

}  // namespace

TEST(ZodiacalLight, TableValuesAtGridPoints) {
  EXPECT_NEAR(zodiacalS10(90.0, 0.0), 259.0 / 1.28, 1e-3);
  EXPECT_NEAR(zodiacalS10(180.0, 0.0), 230.0 / 1.28, 1e-3);  // the gegenschein
  EXPECT_NEAR(zodiacalS10(30.0, 90.0), 77.0 / 1.28, 1e-3);   // the ecliptic pole, any longitude
  EXPECT_NEAR(zodiacalS10(50.0, 0.0), (2.0 * 910.0 + 505.0) / 3.0 / 1.28, 1e-3);  // bilinear on the 15 deg grid
  // Brighter towards the sun along the ecliptic, fainter away from the ecliptic.
  for (double lon = 20.0; lon < 130.0; lon += 5.0) EXPECT_GT(zodiacalS10(lon, 0.0), zodiacalS10(lon + 5.0, 0.0));
  for (double lat = 0.0; lat < 60.0; lat += 5.0) EXPECT_GT(zodiacalS10(90.0, lat), zodiacalS10(90.0, lat + 5.0));
}

TEST(ZodiacalLight, HelioEclipticCoordinatesOfKnownDirections) {
  const glm::dvec3 sun(1.0, 0.0, 0.0);  // the vernal equinox
  const glm::dvec3 pole = glm::dvec3(0.0, -std::sin(shader::kObliquityJ2000Rad), std::cos(shader::kObliquityJ2000Rad));
  EXPECT_NEAR(shader::helioEclipticCoordinates(pole, sun).y, 90.0, 1e-9);
  EXPECT_NEAR(shader::helioEclipticCoordinates(-sun, sun).x, 180.0, 1e-9);
  const glm::dvec3 summerSolstice(0.0, std::cos(shader::kObliquityJ2000Rad), std::sin(shader::kObliquityJ2000Rad));
  const glm::dvec2 ll = shader::helioEclipticCoordinates(summerSolstice, sun);
  EXPECT_NEAR(ll.x, 90.0, 1e-9);
  EXPECT_NEAR(ll.y, 0.0, 1e-9);
}

// After dusk the zodiacal light rises from the western horizon along the ecliptic: at the same
// altitude it is brighter there than away from the sun.
TEST(ZodiacalLight, BrighterAlongTheEclipticNearTheSunAfterDusk) {
  const SkyState s = afterDusk();
  const auto sky = nightDiffuseSky(s);
  ASSERT_TRUE(sky.has_value());
  const double altitude = 20.0;
  double best = 1e9, eclipticAz = 0.0;
  for (double az = 0.0; az < 360.0; az += 1.0) {
    const glm::dvec2 ll = shader::helioEclipticCoordinates(sky->enuToJ2000 * view(az, altitude), sky->sunJ2000);
    if (ll.x < 90.0 && ll.y < best) {
      best = ll.y;
      eclipticAz = az;
    }
  }
  ASSERT_LT(best, 1.0);
  const double sunAz = s.sunAzimuth / kDeg;
  EXPECT_LT(std::abs(std::remainder(eclipticAz - sunAz, 360.0)), 60.0);
  const double near = y709(nightDiffuseRadiance(*sky, view(eclipticAz, altitude)).zodiacal);
  for (double away : {sunAz + 180.0, sunAz + 90.0, sunAz - 90.0}) {
    const double far = y709(nightDiffuseRadiance(*sky, view(away, altitude)).zodiacal);
    EXPECT_GT(near, 2.0 * far) << "azimuth " << away;
  }
}

TEST(Airglow, VanRhijnClosedForm) {
  const double R = shader::kAirglowEarthRadiusM, h = shader::kAirglowLayerHeightM;
  EXPECT_DOUBLE_EQ(shader::vanRhijnFactor(1.0, R, h), 1.0);
  const double horizon = 1.0 / std::sqrt(1.0 - (R / (R + h)) * (R / (R + h)));
  EXPECT_NEAR(shader::vanRhijnFactor(0.0, R, h), horizon, 1e-12);
  EXPECT_NEAR(horizon, 6.01, 0.01);
  // Near the zenith the layer is flat: 1 / cos z.
  EXPECT_NEAR(shader::vanRhijnFactor(std::cos(30.0 * kDeg), R, h), 1.0 / std::cos(30.0 * kDeg), 0.01);
  double last = 0.0;
  for (double z = 0.0; z <= 90.0; z += 5.0) {
    const double f = shader::vanRhijnFactor(std::cos(z * kDeg), R, h);
    EXPECT_GT(f, last);
    last = f;
  }
}

// Brighter near the horizon than at the zenith, even after the longer path's extinction;
// zero below the horizon (the ground hides it).
TEST(Airglow, BrighterAtTheHorizonThanAtTheZenith) {
  const SkyState s = afterDusk();
  const auto sky = nightDiffuseSky(s);
  ASSERT_TRUE(sky.has_value());
  const glm::dvec3 zenithRgb = nightDiffuseRadiance(*sky, view(0.0, 90.0)).airglow;
  const glm::dvec3 expected = shader::s10ToCdM2(kAirglowZenithS10) * airglowRec709() * nightExtinction(*sky, view(0.0, 90.0));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(zenithRgb[c], expected[c], 1e-12);
  const double zenith = y709(zenithRgb);
  // The van Rhijn factor outgrows the extinction (6x against 1/4 at 3 deg, from 1500 m).
  EXPECT_GT(y709(nightDiffuseRadiance(*sky, view(123.0, 3.0)).airglow), zenith);
  for (double alt : {10.0, 20.0}) EXPECT_GT(y709(nightDiffuseRadiance(*sky, view(123.0, alt)).airglow), 1.5 * zenith);
  EXPECT_EQ(y709(nightDiffuseRadiance(*sky, view(123.0, -5.0)).total()), 0.0);
}

TEST(NightDiffuse, FiniteAndNonNegativeEverywhere) {
  const SkyState s = afterDusk();
  const auto sky = nightDiffuseSky(s);
  ASSERT_TRUE(sky.has_value());
  for (double alt = -90.0; alt <= 90.0; alt += 7.5)
    for (double az = 0.0; az < 360.0; az += 15.0) {
      const glm::dvec3 t = nightDiffuseRadiance(*sky, view(az, alt)).total();
      for (int c = 0; c < 3; ++c) {
        EXPECT_TRUE(std::isfinite(t[c]));
        EXPECT_GE(t[c], 0.0);
      }
    }
  EXPECT_THROW(nightDiffuseRadiance(*sky, glm::dvec3(0.0)), std::invalid_argument);
  EXPECT_THROW(nightDiffuseRadiance(*sky, glm::dvec3(std::nan(""), 0.0, 1.0)), std::invalid_argument);
}

// The night's own light on the ground: airglow, zodiacal light and starlight give ~1e-3 lux on a
// horizontal surface at a dark site (Roach & Gordon 1973: about 145 + 60 + 15 S10 at the zenith).
// The eye adapts to the whole view sphere: its upper half is at least as bright on average as a
// uniform sky of that illuminance (E / pi; the airglow brightens towards the horizon), the lower
// half is the terrain under it, so the level is at least half of E / pi.
TEST(NightDiffuse, AdaptationIncludesTheNightsOwnLight) {
  const SkyState s = afterDusk();
  const double lux = shader::rec709Luminance(nightDiffuseIlluminance(*s.ephemeris, s.extinction));
  EXPECT_GT(lux, 3e-4);
  EXPECT_LT(lux, 3e-3);
  EXPECT_GE(s.worldAdaptationLuminance, 0.5 * lux / M_PI);
  ObserverState o = s.observer;
  const SkyState overridden = buildSkyState(o, SkyConditions{}, SunOverride{270.0, -30.0});
  EXPECT_FALSE(nightDiffuseSky(overridden).has_value());  // no time and place: no night sky
}
