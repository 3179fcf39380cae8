// The moon's disc on the CPU (physics/moon/moon_disc.h): its reflectance law against eq. 9 of
// Wang, Ji & Zhang 2011 (corrected; Jensen et al. 2001), its illuminance on the ground, its
// colour through the atmosphere, the albedo map's orientation and the moonlit sky.
#include "ephemeris/night_irradiance.h"
#include "physics/moon/moon_physics.h"
#include "physics/moon/moon_disc.h"
#include "physics/moon/moon_light.h"
#include "physics/physics.h"
#include "tests/physics/atmosphere/shared_models.h"
#include "tests/physics/night/moon_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <cstdlib>
#include <stdexcept>
#include <string>

using namespace skyig;
using namespace skyig::sky;
using namespace skyig::sky::night;
using namespace skyig::sky::testing;

namespace {

constexpr double kPi = std::numbers::pi;

// Eq. 9 in lux: the ephemeris' irradiance (W/m^2 of sunlight) over the solar constant, times the
// sun's illuminance (the renderer's 128 klx).
double eq9Lux(const MoonPlacement& p) {
  return ephemeris::moonIrradiance(p.phaseAngleRad, p.distanceKm, p.sunMoonDistanceKm) /
         ephemeris::kSolarConstantWm2 * shader::SOLAR_ILLUMINANCE_LX;
}

}  // namespace

// The Lommel-Seeliger sphere's disc integral is eq. 9's phase law: int mu0 mu/(mu0 + mu) dA =
// pi/2 F(phi) (the shader's law, summed over the visible hemisphere's projection).
TEST(MoonReflectance, LommelSeeligerDiscIntegralIsTheEq9PhaseLaw) {
  const glm::dvec3 centre(0, 1, 0), toObserver(0, -1, 0);
  for (double phaseDeg = 0.0; phaseDeg <= 170.0; phaseDeg += 10.0) {
    const double phi = phaseDeg * kDeg;
    const glm::dvec3 toSun(std::sin(phi), -std::cos(phi), 0.0);
    constexpr int kGrid = 800;
    double sum = 0.0;
    for (int i = 0; i < kGrid; ++i)
      for (int j = 0; j < kGrid; ++j) {
        const glm::dvec3 q(2.0 * (i + 0.5) / kGrid - 1.0, 0.0, 2.0 * (j + 0.5) / kGrid - 1.0);
        if (glm::dot(q, q) >= 1.0) continue;
        const glm::dvec3 n = shader::moonSurfaceNormal(q, centre);
        sum += shader::lommelSeeliger(glm::dot(n, toSun), glm::dot(n, toObserver));
      }
    sum *= 4.0 / (kGrid * kGrid);
    const double expected = kPi / 2.0 * ephemeris::lunarPhaseLaw(phi);
    EXPECT_NEAR(sum, expected, 0.005 * expected + 2e-4) << "phase " << phaseDeg << " deg";
  }
}

// The first quarter is a tenth of the full moon, not a smooth sphere's third: Krisciunas &
// Schaefer (1991), 2.6 magnitudes, 0.091, plus the earthshine on the dark half.
TEST(MoonDisc, FirstQuarterIsATenthOfTheFullMoon) {
  const double full = shader::rec709Luminance(makeMoonDisc(placeMoon(150.0, 50.0, 0.0, 30.0), nullptr).irradianceRec709);
  const double quarter = shader::rec709Luminance(makeMoonDisc(placeMoon(150.0, 50.0, 90.0, 30.0), nullptr).irradianceRec709);
  EXPECT_NEAR(quarter / full, 0.0911, 0.004);
}

// With the albedo map and earthshine, the rendered disc's irradiance is the moon's (eq. 9 with
// the measured phase function, ephemeris::moonIrradiance) at every phase and every orientation
// of the bright limb (outside the atmosphere).
TEST(MoonDisc, IrradianceMatchesEq9OverPhase) {
  for (double phaseDeg = 0.0; phaseDeg <= 170.0; phaseDeg += 17.0)
    for (double limbDeg : {30.0, 250.0}) {
      const MoonPlacement p = placeMoon(150.0, 50.0, phaseDeg, limbDeg);
      const MoonDisc d = makeMoonDisc(p, nullptr);
      const double expected = eq9Lux(p);
      EXPECT_NEAR(integratedLux(d, 400), expected, 0.02 * expected) << "phase " << phaseDeg << ", limb " << limbDeg;
      EXPECT_NEAR(shader::rec709Luminance(d.irradianceRec709), expected, 0.02 * expected);
    }
}

// A full moon at the zenith lights the ground with 0.1-0.3 lux (published range; about 0.25 for
// an average full moon). The measured moon's V = -12.73 (Krisciunas & Schaefer 1991) gives
// 0.29 lux above the atmosphere (docs/night-sky.md, "The measured moon").
TEST(MoonDisc, FullMoonAtZenithLightsTheGroundWithAQuarterLux) {
  const MoonDisc d = makeMoonDisc(placeMoon(0.0, 89.9, 0.0), seaLevelExtinction());
  const double lux = moonIlluminanceLux(d);
  EXPECT_GT(lux, 0.2);
  EXPECT_LT(lux, 0.3);
  // The atmosphere takes its share: less than above it, but not much at the zenith.
  const double above = shader::rec709Luminance(d.irradianceRec709);
  EXPECT_LT(lux, 0.95 * above);
  EXPECT_GT(lux, 0.6 * above);
}

TEST(MoonDisc, SetMoonGivesNoIlluminance) {
  EXPECT_EQ(moonIlluminanceLux(makeMoonDisc(placeMoon(0.0, -5.0, 0.0), seaLevelExtinction())), 0.0);
}

// Near the horizon the moon is dimmer and redder than high up (the transmittance of the same
// medium as the day sky).
TEST(MoonDisc, ExtinctionDimsAndReddensNearTheHorizon) {
  const MoonDisc high = makeMoonDisc(placeMoon(180.0, 60.0, 0.0), seaLevelExtinction());
  const MoonDisc low = makeMoonDisc(placeMoon(180.0, 2.0, 0.0), seaLevelExtinction());
  const MoonRadiance h = moonDiscRadiance(high, high.centreSeen);
  const MoonRadiance l = moonDiscRadiance(low, low.centreSeen);
  ASSERT_GT(h.luminanceCdM2, 0.0);
  ASSERT_GT(l.luminanceCdM2, 0.0);
  EXPECT_LT(l.luminanceCdM2, 0.5 * h.luminanceCdM2);
  EXPECT_GT(l.rec709.r / l.rec709.b, 1.5 * (h.rec709.r / h.rec709.b));
}

// The half of the disc towards the bright limb's position angle is the lit one, and the lit
// side of the ephemeris' moon faces the sun's direction on the sky.
TEST(MoonDisc, LitSideFacesTheSun) {
  const std::optional<ObserverState> night = nightWithMoon(70.0, 110.0, 20.0);
  ASSERT_TRUE(night.has_value());
  const SkyState s = buildSkyState(*night, SkyConditions{});
  const MoonDisc d = *s.moonDisc;
  const glm::dvec3 sun = enuDirection(s.ephemeris->sun.azimuthRad, s.ephemeris->sun.altitudeRad);
  const glm::dvec3 towardSunOnSky = glm::normalize(sun - glm::dot(sun, d.centre) * d.centre);
  const double offset = 0.6 * std::sin(d.angularRadiusRad);
  const double sunward = moonDiscRadiance(d, d.centreSeen + offset * towardSunOnSky).luminanceCdM2;
  const double away = moonDiscRadiance(d, d.centreSeen - offset * towardSunOnSky).luminanceCdM2;
  EXPECT_GT(sunward, 100.0 * away) << "sunward " << sunward << ", away " << away;
}

// Selenographic east faces the observer's west: Mare Crisium (59 E) is on the right of a
// southern moon seen from the north, and the map is dark there (a mare).
TEST(MoonDisc, AlbedoMapFacesTheEarthWithCrisiumOnTheWest) {
  const MoonDisc d = makeMoonDisc(placeMoon(180.0, 30.0, 0.0), nullptr);
  EXPECT_LT(d.east.x, -0.9);  // ENU: west
  const glm::dvec3 toObserver = -d.centre;
  const double lon = 59.0 * kDeg, lat = 17.0 * kDeg;
  const glm::dvec3 n = std::cos(lat) * (std::cos(lon) * toObserver + std::sin(lon) * d.east) + std::sin(lat) * d.north;
  const glm::dvec2 uv = shader::selenographicUv(n, toObserver, d.north, d.east);
  EXPECT_LT(d.albedo->sample(uv.x, uv.y), 0.75);  // maria: about half the highlands' albedo
  const glm::dvec2 highland = shader::selenographicUv(std::cos(lat) * toObserver - std::sin(lat) * d.north +
                                                          0.0 * d.east, toObserver, d.north, d.east);
  EXPECT_GT(d.albedo->sample(highland.x, highland.y), 1.0);  // south of the centre: highlands
}

TEST(MoonDisc, RejectsBadPlacements) {
  MoonPlacement p = placeMoon(0.0, 30.0, 0.0);
  p.phaseAngleRad = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(makeMoonDisc(p, nullptr), std::invalid_argument);
  p = placeMoon(0.0, 30.0, 0.0);
  p.distanceKm = 1000.0;
  EXPECT_THROW(makeMoonDisc(p, nullptr), std::invalid_argument);
  EXPECT_THROW(moonDiscRadiance(makeMoonDisc(placeMoon(0.0, 30.0, 0.0), nullptr), glm::dvec3(0.0)),
               std::invalid_argument);
}

// Moonlight is sunlight made redder by the lunar soil, a few millionths of it at full moon
// (V = -12.73 against the sun's -26.74: 2.5e-6).
TEST(Moonlight, ScaleIsAMillionthOfSunlightAndRedder) {
  const std::optional<ObserverState> night = nightWithMoon(0.0, 15.0, 20.0);
  ASSERT_TRUE(night.has_value());
  const SkyState s = buildSkyState(*night, SkyConditions{});
  EXPECT_GT(s.moonlightScale.g, 1e-6);
  EXPECT_LT(s.moonlightScale.g, 4e-6);
  EXPECT_GT(s.moonlightScale.r, s.moonlightScale.g);
  EXPECT_GT(s.moonlightScale.g, s.moonlightScale.b);
  EXPECT_NEAR(glm::length(s.moonDirection), 1.0, 1e-12);
  EXPECT_GT(s.moonDirection.z, 0.3);
  // Overridden sun: no ephemeris, no moon.
  const SkyState day = buildSkyState(*night, SkyConditions{}, SunOverride{180.0, 30.0});
  EXPECT_EQ(day.moonlightScale, glm::dvec3(0.0));
  EXPECT_EQ(day.moonDisc, nullptr);
}

// The full-moon sky is a dim blue: bluer than the moonlight that lights it, and near the zenith
// 18-20 mag/arcsec^2 in V (Krisciunas & Schaefer 1991, fig. 2: 1e-3 to 7e-3 cd/m^2) for a
// full moon 40-60 degrees up.
TEST(Moonlight, FullMoonSkyIsADimBlue) {
  const auto model = atmosphere::testing::cachedModel(atmosphere::testing::smallEarthConfig());
  SkyState s;
  s.observer.heightM = 0.0;
  s.moonDirection = enuDirection(0.0, 50.0 * kDeg);
  const double fullMoon = 2.0 / 3.0 * ephemeris::kMoonAlbedo * std::pow(ephemeris::kMoonRadiusKm / 384400.0, 2);
  s.moonlightScale = fullMoon * moonlightColour() / sunlightColour();
  const MoonRadiance zenith = moonlitSkyRadiance(model, s, glm::dvec3(0, 0, 1));
  EXPECT_GT(zenith.luminanceCdM2, 1e-3);
  EXPECT_LT(zenith.luminanceCdM2, 7e-3);
  EXPECT_GT(zenith.rec709.b / zenith.rec709.r, 1.2 * moonlightColour().b / moonlightColour().r);
  s.moonlightScale = glm::dvec3(0.0);
  EXPECT_EQ(moonlitSkyRadiance(model, s, glm::dvec3(0, 0, 1)).luminanceCdM2, 0.0);
}

// The map is found through SKYIG_DATA_DIR when it is set, and a missing map is named.
TEST(MoonAlbedoMap, DataDirectoryOverrideAndMissingFile) {
  const std::string staged = std::getenv("SKYIG_DATA_DIR");  // tests/staged_data_dir.cpp
  ASSERT_EQ(::setenv("SKYIG_DATA_DIR", "/nonexistent-skyig-data", 1), 0);
  const std::string path = moonAlbedoPath();
  ASSERT_EQ(::setenv("SKYIG_DATA_DIR", staged.c_str(), 1), 0);
  EXPECT_EQ(path, "/nonexistent-skyig-data/moon.png");
  try {
    MoonAlbedo::load(path);
    FAIL() << "a missing map loaded";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_EQ(moonAlbedoPath(), staged + "/moon.png");
}

// The disc is refracted by the ephemeris' own formula (Saemundsson at the observer's air): its
// centre sits where the ephemeris puts it, and near the horizon its lower limb is lifted more
// than its upper one, by the difference of the formula at the two limbs.
TEST(MoonDisc, RefractionIsTheEphemerisOwnAndFlattensTheDisc) {
  MoonPlacement p = placeMoon(120.0, 0.3, 0.0);
  p.pressureHpa = 1013.25;
  p.temperatureC = 15.0;
  const double r = skyig::ephemeris::refractionSaemundsson(p.altitudeRad, p.pressureHpa, p.temperatureC);
  p.altitudeRefractedRad = p.altitudeRad + r;
  const MoonDisc d = makeMoonDisc(p, seaLevelExtinction());
  EXPECT_NEAR(d.refraction.x, p.altitudeRefractedRad, 1e-15);
  EXPECT_NEAR(d.refraction.y, r, 1e-15);
  // Refraction falls with apparent altitude near the horizon, and the expansion's slope is the
  // formula's: R(a + R(a)) at the limbs against the quadratic.
  EXPECT_LT(d.refraction.z, 0.0);
  const double radius = d.angularRadiusRad;
  for (double sign : {-1.0, 1.0}) {
    const double airless = p.altitudeRad + sign * radius;
    const double seen = airless + skyig::ephemeris::refractionSaemundsson(airless, p.pressureHpa, p.temperatureC);
    const double dh = seen - d.refraction.x;
    const double model = d.refraction.y + d.refraction.z * dh + d.refraction.w * dh * dh;
    EXPECT_NEAR(model, seen - airless, 1e-6) << sign;  // 0.2 arcsec (0.05 measured at 0.3 deg)
  }
  // The seen disc is shorter than it is wide by the difference of the lifts, ~5 arcmin here.
  const double lower = skyig::ephemeris::refractionSaemundsson(p.altitudeRad - radius, 1013.25, 15.0);
  const double upper = skyig::ephemeris::refractionSaemundsson(p.altitudeRad + radius, 1013.25, 15.0);
  EXPECT_GT((lower - upper) * 180.0 / std::numbers::pi * 60.0, 3.0);
  p.pressureHpa = -1.0;
  EXPECT_THROW(makeMoonDisc(p, seaLevelExtinction()), std::invalid_argument);
}
