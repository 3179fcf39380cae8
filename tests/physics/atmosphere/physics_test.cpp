// Physical facts the full model must show, and the reference values of a clear Earth
// atmosphere (those of Bruneton's 2017 implementation with its default parameters, 4
// orders, 47 wavelengths; skyig uses 16 wavelengths and small test tables, hence the
// tolerances).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "physics/atmosphere/conditions.h"
#include "shared_models.h"

namespace skyig::atmosphere {
namespace {

using testing::cachedModel;
using testing::oneGroupConfig;
using testing::smallEarthConfig;

const glm::dvec3 kUp(0.0, 0.0, 1.0);

double zenithLuminance(const AtmosphereModel& model, double sunZenithDeg, double altitudeM = 0.0) {
  const glm::dvec3 camera = observerPosition(model.config().medium, altitudeM);
  const glm::dvec3 sun = directionFromAngles(sunZenithDeg * kDegree, 0.0);
  return model.converter().luminance(model.skyRadiance(camera, kUp, sun));
}

// Tiny tables, two orders: enough for exact linearity checks, computed in well under a second.
ModelConfig tinyConfig() {
  ModelConfig c = oneGroupConfig();
  c.sizes = testing::tinySizes();
  c.sizes.transmittanceMu = 32;
  c.options.scatteringOrders = 2;
  return c;
}

TEST(AtmospherePhysics, NoSunNoSky) {
  ModelConfig c = tinyConfig();
  c.medium.solarIrradianceScale = 0.0;
  const AtmosphereModel model(c);
  const glm::dvec3 camera = observerPosition(c.medium, 1000.0);
  for (double sunZenith : {0.0, 60.0, 89.0, 95.0}) {
    const glm::dvec3 sun = directionFromAngles(sunZenith * kDegree, 0.0);
    for (double viewZenith : {0.0, 45.0, 89.0, 91.0, 120.0}) {
      const glm::dvec3 view = directionFromAngles(viewZenith * kDegree, 0.5);
      for (double v : model.skyRadiance(camera, view, sun)) EXPECT_EQ(v, 0.0);
      for (double v : model.skyIrradiance(camera, kUp, sun)) EXPECT_EQ(v, 0.0);
      for (double v : model.sunIrradiance(camera, kUp, sun)) EXPECT_EQ(v, 0.0);
    }
  }
}

TEST(AtmospherePhysics, TwiceTheSunTwiceTheRadiance) {
  ModelConfig c1 = tinyConfig();
  ModelConfig c2 = c1;
  c2.medium.solarIrradianceScale = 2.0;
  const AtmosphereModel m1(c1);
  const AtmosphereModel m2(c2);
  const glm::dvec3 camera = observerPosition(c1.medium, 500.0);
  int checked = 0;
  for (double sunZenith : {10.0, 70.0, 92.0}) {
    const glm::dvec3 sun = directionFromAngles(sunZenith * kDegree, 0.0);
    for (double viewZenith : {0.0, 60.0, 89.5, 100.0}) {
      const glm::dvec3 view = directionFromAngles(viewZenith * kDegree, 1.0);
      const Spectrum l1 = m1.skyRadiance(camera, view, sun);
      const Spectrum l2 = m2.skyRadiance(camera, view, sun);
      for (std::size_t i = 0; i < l1.size(); ++i) {
        ASSERT_GT(l1[i], 0.0);
        EXPECT_NEAR(l2[i] / l1[i], 2.0, 1e-12);
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 48);
}

TEST(AtmospherePhysics, ZenithLuminanceFollowsTheSun) {
  const AtmosphereModel model = cachedModel(smallEarthConfig());
  const double l30 = zenithLuminance(model, 30.0);
  const double l90 = zenithLuminance(model, 90.0);
  const double l96 = zenithLuminance(model, 96.0);
  std::printf("zenith luminance: sun zenith 30 deg %.1f, 90 deg %.1f, 96 deg %.3f cd/m^2\n", l30,
              l90, l96);
  EXPECT_NEAR(l30, 1700.0, 0.1 * 1700.0);  // reference ~1700 cd/m^2
  EXPECT_NEAR(l90, 160.0, 0.15 * 160.0);   // reference ~160 cd/m^2
  // Reference: below 1 cd/m^2. The 16 mu_s rows of the test tables put it slightly higher.
  EXPECT_LT(l96, 2.0);
  EXPECT_GT(l96, 0.1);
  // Monotonic as the sun sets.
  double previous = zenithLuminance(model, 0.0);
  for (double z = 10.0; z <= 108.0; z += 7.0) {
    const double l = zenithLuminance(model, z);
    EXPECT_LT(l, previous) << "sun zenith " << z;
    previous = l;
  }
}

TEST(AtmospherePhysics, NauticalTwilightEndsBelowAMillicandela) {
  // Sun 18 degrees below the horizon, no moon: the zenith is below 1e-3 cd/m^2.
  const AtmosphereModel model = cachedModel(smallEarthConfig());
  const double l = zenithLuminance(model, 108.0);
  std::printf("zenith luminance with the sun 18 deg down: %.3g cd/m^2\n", l);
  EXPECT_LT(l, 1e-3);
  EXPECT_GT(l, 0.0);
}

TEST(AtmospherePhysics, IlluminanceWithTheSunOverhead) {
  // Reference: ~115 000 lx direct + ~8 000 lx from the sky on a horizontal surface.
  const AtmosphereModel model = cachedModel(smallEarthConfig());
  const glm::dvec3 camera = observerPosition(model.config().medium, 0.0);
  const double direct = model.converter().luminance(model.sunIrradiance(camera, kUp, kUp));
  const double sky = model.converter().luminance(model.skyIrradiance(camera, kUp, kUp));
  std::printf("sun at the zenith: direct %.0f lx, sky %.0f lx\n", direct, sky);
  EXPECT_NEAR(direct, 115000.0, 0.03 * 115000.0);
  EXPECT_NEAR(sky, 8000.0, 0.1 * 8000.0);
}

TEST(AtmospherePhysics, SolarDiscOutsideTheAtmosphere) {
  const AtmosphereModel model = cachedModel(smallEarthConfig());
  const double l = model.converter().luminance(model.solarRadiance());
  EXPECT_NEAR(l, 1.9e9, 0.05 * 1.9e9);  // reference ~1.9e9 cd/m^2
}

TEST(AtmospherePhysics, FromHundredKilometresSpaceIsBlackAndTheLimbBlue) {
  const AtmosphereModel model = cachedModel(smallEarthConfig());
  const Medium& m = model.config().medium;
  const glm::dvec3 camera = observerPosition(m, 100e3);
  const glm::dvec3 sun = directionFromAngles(45.0 * kDegree, 0.0);
  // Straight up the ray never meets the atmosphere.
  EXPECT_EQ(zenithLuminance(model, 45.0, 100e3), 0.0);
  const double groundZenith = zenithLuminance(model, 45.0, 0.0);
  // The limb: a ray grazing 20 km above the ground, 90 degrees in azimuth from the sun.
  const double r = glm::length(camera);
  const double limbZenith = kPi - std::asin((m.bottomRadiusM + 20e3) / r);
  const glm::dvec3 limb = directionFromAngles(limbZenith, kPi / 2.0);
  const Spectrum radiance = model.skyRadiance(camera, limb, sun);
  const glm::dvec3 rgb = model.converter().toRec709(radiance);
  const double luminance = model.converter().luminance(radiance);
  std::printf("limb from 100 km: %.1f cd/m^2, Rec.709 (%.1f, %.1f, %.1f); zenith from the ground %.1f\n",
              luminance, rgb.r, rgb.g, rgb.b, groundZenith);
  EXPECT_GT(luminance, 0.1 * groundZenith);  // it glows
  EXPECT_GT(rgb.b, 1.3 * rgb.r);              // and it is blue
  EXPECT_GT(rgb.b, rgb.g);
  // Above the limb, the sky turns black within a few scale heights.
  const double highZenith = kPi - std::asin((m.bottomRadiusM + 59e3) / r);
  const double high = model.converter().luminance(
      model.skyRadiance(camera, directionFromAngles(highZenith, kPi / 2.0), sun));
  EXPECT_LT(high, 0.02 * luminance);
}

TEST(AtmospherePhysics, HazeWhitensTheHorizon) {
  // Spectral whiteness: the sky's 440/680 nm ratio relative to the sun's. Clear air scatters
  // blue (ratio well above 1); aerosols at 5 km visibility scatter all wavelengths alike.
  ModelConfig clear = oneGroupConfig();
  ModelConfig hazy = clear;
  Conditions conditions;
  conditions.visibilityKm = 5.0;
  hazy.medium = applyConditions(clear.medium, conditions);
  EXPECT_NEAR(visibilityOf(hazy.medium), 5.0, 1e-9);
  const AtmosphereModel clearModel = cachedModel(clear);
  const AtmosphereModel hazyModel = cachedModel(hazy);
  const glm::dvec3 camera = observerPosition(clear.medium, 0.0);
  const glm::dvec3 sun = directionFromAngles(40.0 * kDegree, 0.0);
  const glm::dvec3 horizon = directionFromAngles(88.0 * kDegree, kPi / 2.0);
  auto blueness = [&](const AtmosphereModel& model) {
    const Spectrum l = model.skyRadiance(camera, horizon, sun);
    const Spectrum e = model.solarRadiance();
    return (l[0] / e[0]) / (l[2] / e[2]);
  };
  const double bClear = blueness(clearModel);
  const double bHazy = blueness(hazyModel);
  std::printf("horizon 440/680 nm ratio relative to the sun: clear %.2f, visibility 5 km %.2f\n",
              bClear, bHazy);
  EXPECT_GT(bClear, 1.5);
  EXPECT_LT(bHazy, 1.25);
  EXPECT_GT(bHazy, 0.8);
}

TEST(AtmospherePhysics, NoNanOrInfAcrossTheHorizon) {
  const AtmosphereModel model = cachedModel(smallEarthConfig());
  const Medium& m = model.config().medium;
  int checked = 0;
  for (double altitude : {0.0, 1.0, 1000.0, 59999.0, 60001.0, 100e3, 1e6}) {
    const glm::dvec3 camera = observerPosition(m, altitude);
    const double horizon = kPi - std::asin(std::min(1.0, m.bottomRadiusM / glm::length(camera)));
    for (double sunZenith : {0.0, 89.9, 90.0, 95.0, 119.0, 150.0}) {
      const glm::dvec3 sun = directionFromAngles(sunZenith * kDegree, 0.0);
      for (double dz = -2e-3; dz <= 2e-3; dz += 1e-4) {
        for (double zenith : {horizon + dz, kPi / 2.0 + dz}) {
          const glm::dvec3 view = directionFromAngles(zenith, 0.3);
          Spectrum t;
          const Spectrum l = model.skyRadiance(camera, view, sun, &t);
          for (std::size_t i = 0; i < l.size(); ++i) {
            ASSERT_TRUE(std::isfinite(l[i]) && l[i] >= 0.0) << altitude << " " << zenith;
            ASSERT_TRUE(std::isfinite(t[i]) && t[i] >= 0.0 && t[i] <= 1.0);
          }
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 1500);
}

TEST(AtmospherePhysics, GroundSeenFromAboveHasAerialPerspective) {
  const AtmosphereModel model = cachedModel(smallEarthConfig());
  const Medium& m = model.config().medium;
  const glm::dvec3 sun = directionFromAngles(30.0 * kDegree, 0.0);
  const glm::dvec3 groundPoint(0.0, 0.0, m.bottomRadiusM);
  // The same ground point from 100 m and from 10 km: the far view is more attenuated and has
  // more light scattered in, and the total stays finite and positive.
  Spectrum tNear;
  Spectrum tFar;
  const Spectrum near = model.groundRadiance(observerPosition(m, 100.0), groundPoint, sun, &tNear);
  const Spectrum far = model.groundRadiance(observerPosition(m, 10000.0), groundPoint, sun, &tFar);
  const Spectrum inFar = model.skyRadianceToPoint(observerPosition(m, 10000.0), groundPoint, sun);
  for (std::size_t i = 0; i < near.size(); ++i) {
    EXPECT_GT(tNear[i], tFar[i]);
    EXPECT_GT(inFar[i], 0.0);
    EXPECT_TRUE(std::isfinite(far[i]) && far[i] > 0.0);
  }
  // Lambertian check near the ground: radiance ~ albedo/pi * (E_sun + E_sky).
  const glm::dvec3 n(0.0, 0.0, 1.0);
  const double e = model.converter().luminance(model.sunIrradiance(groundPoint, n, sun)) +
                   model.converter().luminance(model.skyIrradiance(groundPoint, n, sun));
  EXPECT_NEAR(model.converter().luminance(near), m.groundAlbedo / kPi * e, 0.03 * m.groundAlbedo / kPi * e);
}

}  // namespace
}  // namespace skyig::atmosphere

namespace skyig::atmosphere {
namespace {

TEST(AtmosphereSunDisc, LimbDarkenedDiscKeepsTheSolarIrradiance) {
  const AtmosphereModel model = cachedModel(oneGroupConfig());
  const Medium& m = model.config().medium;
  const glm::dvec3 space = observerPosition(m, 1e6);
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.0, 1.0));
  // Irradiance = integral of the radiance over the disc (rings of equal angular width).
  const double radius = m.sunAngularRadiusRad;
  const glm::dvec3 side = glm::normalize(glm::cross(sun, glm::dvec3(0.0, 1.0, 0.0)));
  const int rings = 400;
  Spectrum irradiance(4, 0.0);
  for (int i = 0; i < rings; ++i) {
    const double angle = (i + 0.5) / rings * radius;
    const glm::dvec3 view = std::cos(angle) * sun + std::sin(angle) * side;
    const Spectrum l = model.sunDiscRadiance(space, view, sun);
    const double solidAngle = 2.0 * kPi * std::sin(angle) * (radius / rings);
    for (int k = 0; k < 4; ++k) irradiance[static_cast<std::size_t>(k)] += l[static_cast<std::size_t>(k)] * solidAngle;
  }
  for (std::size_t k = 0; k < 4; ++k) {
    const double expected = coefficientsAt(m, model.wavelengths()[k]).solarIrradiance;
    EXPECT_NEAR(irradiance[k] / expected, 1.0, 0.005) << model.wavelengths()[k] << " nm";
  }
  // Darker at the limb, and more so in the blue (alpha grows as lambda falls).
  const glm::dvec3 limb = std::cos(0.95 * radius) * sun + std::sin(0.95 * radius) * side;
  const Spectrum centre = model.sunDiscRadiance(space, sun, sun);
  const Spectrum edge = model.sunDiscRadiance(space, limb, sun);
  EXPECT_LT(edge[0] / centre[0], edge[2] / centre[2]);
  EXPECT_LT(edge[1] / centre[1], 0.75);
  // Off the disc: nothing.
  const glm::dvec3 off = std::cos(1.05 * radius) * sun + std::sin(1.05 * radius) * side;
  for (double v : model.sunDiscRadiance(space, off, sun)) EXPECT_EQ(v, 0.0);
}

TEST(AtmosphereSunDisc, AttenuatedByTheAtmosphereAndHiddenByTheGround) {
  const AtmosphereModel model = cachedModel(oneGroupConfig());
  const Medium& m = model.config().medium;
  const glm::dvec3 up(0.0, 0.0, 1.0);
  const Spectrum outside = model.sunDiscRadiance(observerPosition(m, 1e6), up, up);
  const Spectrum ground = model.sunDiscRadiance(observerPosition(m, 0.0), up, up);
  const Spectrum t = model.transmittanceToTop(m.bottomRadiusM, 1.0);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(ground[k] / outside[k], t[k], 1e-12);
  // The sun below the horizon of an observer on the ground, and behind the planet from space.
  const glm::dvec3 low = directionFromAngles(91.0 * kDegree, 0.0);
  for (double v : model.sunDiscRadiance(observerPosition(m, 0.0), low, low)) EXPECT_EQ(v, 0.0);
  const glm::dvec3 down(0.0, 0.0, -1.0);
  for (double v : model.sunDiscRadiance(observerPosition(m, 1e6), down, down)) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace skyig::atmosphere

namespace skyig::atmosphere {
namespace {

TEST(AtmospherePhysics, OzoneKeepsTheTwilightZenithBlue) {
  // At twilight the zenith's light crosses the ozone layer on a long slant path; the Chappuis
  // band (around 600 nm) then removes orange and red, which is why the zenith stays blue
  // (Hulburt 1953). Without ozone the same sky is far less blue.
  ModelConfig withOzone = oneGroupConfig();
  withOzone.wavelengthsNm = {440.0, 500.0, 600.0, 680.0};
  ModelConfig withoutOzone = withOzone;
  withoutOzone.medium.ozoneColumnDu = 0.0;
  const AtmosphereModel a = cachedModel(withOzone);
  const AtmosphereModel b = cachedModel(withoutOzone);
  const glm::dvec3 camera = observerPosition(withOzone.medium, 0.0);
  auto blueOverOrange = [&](const AtmosphereModel& model, double sunZenithDeg) {
    const glm::dvec3 sun = directionFromAngles(sunZenithDeg * kDegree, 0.0);
    const Spectrum l = model.skyRadiance(camera, kUp, sun);
    const Spectrum e = model.solarRadiance();
    return (l[0] / e[0]) / (l[2] / e[2]);
  };
  const double twilightWith = blueOverOrange(a, 96.0);
  const double twilightWithout = blueOverOrange(b, 96.0);
  const double noonWith = blueOverOrange(a, 30.0);
  const double noonWithout = blueOverOrange(b, 30.0);
  std::printf("zenith 440/600 nm ratio relative to the sun: sun 30 deg %.2f (no ozone %.2f), "
              "sun 96 deg %.2f (no ozone %.2f)\n",
              noonWith, noonWithout, twilightWith, twilightWithout);
  EXPECT_GT(twilightWith, 1.5 * twilightWithout);
  EXPECT_LT(noonWith, 1.15 * noonWithout);  // in daylight ozone matters little
}

}  // namespace
}  // namespace skyig::atmosphere
