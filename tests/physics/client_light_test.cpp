// The light a client image generator shades its terrain with (sky/client_light.h), against the probe
// and against independent integrals of the sky skyig draws.
#include "sky/client_light.h"

#include "physics/atmosphere/probe.h"
#include "physics/goggle/nvis_sky.h"
#include "physics/night/night_diffuse.h"
#include "physics/stars/star_field.h"
#include "sky/sky_state.h"
#include "tests/physics/atmosphere/shared_models.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <vector>

using namespace skyig;
using namespace skyig::sky;

namespace {

constexpr double kPi = std::numbers::pi;
using skyig::kDeg;

// Rec.709 luminance with skyig's weights (physics/common/color.glsl).
double luminance(const glm::dvec3& c) { return 0.2126729 * c.r + 0.7151522 * c.g + 0.0721750 * c.b; }

// The Bruneton 2017 Earth, small tables (through the test cache).
std::shared_ptr<const atmosphere::AtmosphereModel> model() {
  static const auto m = std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::testing::cachedModel(atmosphere::testing::smallEarthConfig()));
  return m;
}

// The physical sky for an observer 500 m up, the sun at `altitudeDeg` in the south-east.
SkyState physicalState(double altitudeDeg) {
  ObserverState o;
  o.latitudeDeg = 47.0;
  o.longitudeDeg = 11.0;
  o.heightM = 500.0;
  o.utc = {2026, 6, 21, 12 * 3600.0};
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = model();
  return buildSkyState(o, c, SunOverride{135.0, altitudeDeg});
}

// A brute-force hemisphere integral of the model's sky radiance, independent of hostLight's
// equal-area cells: the midpoint rule in zenith angle and azimuth, d(omega) = sin(theta).
glm::dvec3 bruteForceHorizontalIrradiance(const SkyState& s) {
  const atmosphere::AtmosphereModel& m = *model();
  const glm::dvec3 camera(0.0, 0.0, m.parameters(0).bottom_radius + s.observer.heightM);
  const glm::dvec3 sun = enuDirection(s.sunAzimuth, s.sunAltitude);
  constexpr int kTheta = 90, kPhi = 90;
  const double dTheta = 0.5 * kPi / kTheta, dPhi = 2.0 * kPi / kPhi;
  glm::dvec3 e(0.0);
  for (int i = 0; i < kTheta; ++i) {
    const double theta = (i + 0.5) * dTheta;
    for (int j = 0; j < kPhi; ++j) {
      const double phi = (j + 0.5) * dPhi;
      const glm::dvec3 v(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      e += m.converter().toRec709(m.skyRadiance(camera, v, sun)) * std::cos(theta) * std::sin(theta) * dTheta * dPhi;
    }
  }
  return e;
}

// The physical sky 600 m up near Innsbruck at `utc`, as buildSkyState makes it (ephemeris,
// moon, night light).
SkyState nightOverTheAlps(const ephemeris::UtcTime& utc) {
  ObserverState o;
  o.latitudeDeg = 47.26;
  o.longitudeDeg = 11.34;
  o.heightM = 600.0;
  o.utc = utc;
  SkyConditions c;
  c.model = SkyModel::Physical;
  c.atmosphere = model();
  return buildSkyState(o, c);
}

}  // namespace

// The sun the client lights with is the probe's: `skyig probe --irradiance`'s direct_sun_lux for
// the same observer and sun, at noon and at sunset.
TEST(ClientLight, HostSunIlluminanceIsTheProbes) {
  for (double altitudeDeg : {60.0, 2.0}) {
    const SkyState s = physicalState(altitudeDeg);
    atmosphere::ProbeRequest r;
    r.altitudeM = s.observer.heightM;
    r.sunZenithDeg = 90.0 - s.sunAltitude / kDeg;
    r.sunAzimuthDeg = s.sunAzimuth / kDeg;
    r.irradiance = true;
    const double probeLux = atmosphere::probe(*model(), r).irradiance->directSunLux;
    const ClientLight light = clientLight(s, model().get());
    EXPECT_NEAR(light.sun.horizontalLux, probeLux, 1e-9 * probeLux) << "sun at " << altitudeDeg << " deg";
    // Facing the sun, the horizontal figure over the sine of the altitude; a colour of luminance 1.
    EXPECT_NEAR(light.sun.normalLux * std::sin(altitudeDeg * kDeg), light.sun.horizontalLux, 0.01 * probeLux);
    EXPECT_NEAR(luminance(light.sun.colour), 1.0, 1e-9);
    EXPECT_NEAR(light.sun.direction.z, std::sin(altitudeDeg * kDeg), 1e-12);
  }
}

// At sunset the sunlight is redder than at noon (the blue scattered out of the longer path).
TEST(ClientLight, SunsetSunlightIsRedderThanNoon) {
  const ClientLight noon = clientLight(physicalState(60.0), model().get());
  const ClientLight sunset = clientLight(physicalState(2.0), model().get());
  EXPECT_GT(sunset.sun.colour.r / sunset.sun.colour.b, 1.5 * noon.sun.colour.r / noon.sun.colour.b);
  EXPECT_LT(sunset.sun.horizontalLux, 0.05 * noon.sun.horizontalLux);
}

TEST(ClientLight, AmbientIrradianceIsTheHemisphereIntegralOfTheSky) {
  for (double altitudeDeg : {60.0, 2.0}) {
    const SkyState s = physicalState(altitudeDeg);
    const ClientLight light = clientLight(s, model().get());
    const glm::dvec3 reference = bruteForceHorizontalIrradiance(s);
    EXPECT_NEAR(light.ambientHorizontalLux, luminance(reference), 0.02 * luminance(reference)) << altitudeDeg;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(light.ambientHorizontalRec709[c], reference[c], 0.02 * reference[c]) << altitudeDeg << " channel " << c;
  }
}

// Ramamoorthi & Hanrahan (2001): nine coefficients carry the irradiance, within the error of
// the band-limited clamped cosine (their analysis: at most 9% for any lighting; average errors of about 1% in their examples).
// Here 5.4% (noon) and 5.8% (sunset) high for the zenith normal: the sharp step from the sky to
// the darker ground at the horizon is what nine terms smooth out.
TEST(ClientLight, SphericalHarmonicsReproduceTheIrradiance) {
  for (double altitudeDeg : {60.0, 2.0}) {
    const ClientLight light = clientLight(physicalState(altitudeDeg), model().get());
    const double fromSh = luminance(shIrradiance(light.skySh, {0.0, 0.0, 1.0}));
    EXPECT_NEAR(fromSh, light.ambientHorizontalLux, 0.08 * light.ambientHorizontalLux) << altitudeDeg;
  }
}

// A uniform radiance L over the whole sphere has only L00 = L sqrt(4 pi) (Y00 = 1 / sqrt(4 pi)),
// and every surface receives pi L from it, whatever its normal.
TEST(ClientLight, UniformRadianceGivesPiTimesItsRadiance) {
  ShCoefficients sh{};
  const glm::dvec3 radiance(2.0, 3.0, 5.0);
  sh[0] = radiance * std::sqrt(4.0 * kPi);
  for (const glm::dvec3& n : {glm::dvec3(0.0, 0.0, 1.0), glm::dvec3(0.6, 0.0, -0.8), glm::dvec3(0.0, -1.0, 0.0)}) {
    const glm::dvec3 e = shIrradiance(sh, n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(e[c], kPi * radiance[c], 1e-5 * kPi * radiance[c]);
  }
}

// The frame's adaptation is the state's.
TEST(ClientLight, AdaptationIsTheStates) {
  const SkyState s = physicalState(30.0);
  const ClientLight light = clientLight(s, model().get());
  EXPECT_EQ(light.adaptationLuminance, s.worldAdaptationLuminance);
  EXPECT_EQ(light.adaptationGain, s.adaptationGain);
}

// Under the analytic sky the sun is the analytic model's own lighting.
TEST(ClientLight, AnalyticSunIsTheModelsLighting) {
  ObserverState o;
  o.utc = {2026, 6, 21, 12 * 3600.0};
  const SkyState s = buildSkyState(o, SkyConditions{}, SunOverride{180.0, 45.0});
  const ClientLight light = clientLight(s, nullptr);
  EXPECT_NEAR(light.sun.horizontalLux, luminance(s.sky.lighting.directHorizontal), 1e-9 * light.sun.horizontalLux);
  EXPECT_GT(light.ambientHorizontalLux, 0.0);
}

// Along the horizontal view, a point far enough away shows the sky's horizon radiance whatever
// its own colour: the haze in front of it is the horizon sky.
TEST(ClientLight, DistantPointTendsToTheHorizonRadiance) {
  const SkyState s = physicalState(30.0);
  const glm::dvec3 view(0.0, 1.0, 0.0);  // north, horizontal
  const double horizon = luminance(clientSkyRadiance(s, model().get(), view));
  const glm::dvec3 own(0.0);  // a black surface: what is seen is the haze alone
  double lastError = 1e30;
  for (double d : {1e3, 1e4, 1e5, 3e5}) {
    const ClientAerialPerspective ap = clientAerialPerspective(s, *model(), view * d);
    const double seen = luminance(own * ap.transmittance + ap.inScattered);
    const double error = std::abs(seen - horizon) / horizon;
    EXPECT_LT(error, lastError) << d;
    lastError = error;
  }
  EXPECT_LT(lastError, 0.1);
}

// Ten metres away a sunlit surface keeps its radiance and colour.
TEST(ClientLight, NearPointKeepsItsOwnColour) {
  const SkyState s = physicalState(30.0);
  const ClientLight light = clientLight(s, model().get());
  const glm::dvec3 own = glm::dvec3(0.3, 0.2, 0.1) * (light.sun.horizontalLux + light.ambientHorizontalLux) / kPi;
  const ClientAerialPerspective ap = clientAerialPerspective(s, *model(), {0.0, 10.0, -1.0});
  for (int c = 0; c < 3; ++c) EXPECT_GT(ap.transmittance[c], 0.999);
  const glm::dvec3 seen = own * ap.transmittance + ap.inScattered;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], own[c], 0.01 * own[c]) << c;
}

// The full moon of 3 January 2026, high over the Alps near midnight: the moon is the probe's
// moon_lux (0.1-0.4 lux for a high full moon), facing it brighter by 1 / sin(altitude), and the
// sky it lights adds an ambient a few percent to a few tens of percent of it, as the sun's sky
// does by day.
TEST(ClientLight, FullMoonLightsTheNight) {
  const SkyState s = nightOverTheAlps({2026, 1, 3, 23 * 3600.0});
  ASSERT_TRUE(s.moonDisc);
  ASSERT_GT(s.moonDisc->centreSeen.z, std::sin(40.0 * kDeg));
  const ClientLight light = clientLight(s, model().get());
  EXPECT_EQ(light.moon.horizontalLux, moonIlluminanceLux(s));
  EXPECT_GT(light.moon.horizontalLux, 0.1);
  EXPECT_LT(light.moon.horizontalLux, 0.4);
  EXPECT_NEAR(light.moon.normalLux * s.moonDisc->centreSeen.z, light.moon.horizontalLux, 1e-9);
  EXPECT_NEAR(luminance(light.moon.colour), 1.0, 1e-9);
  EXPECT_NEAR(glm::length(light.moon.direction), 1.0, 1e-12);
  EXPECT_GT(light.ambientHorizontalLux, 0.02 * light.moon.horizontalLux);
  EXPECT_LT(light.ambientHorizontalLux, 0.3 * light.moon.horizontalLux);
}

// On a moonless night far from the sun the terrain is lit by the night's own light: the
// ambient a client gets is the diffuse night light's illuminance (airglow, zodiacal light, the
// Milky Way's floor, integrated over 8 x 16 directions by physics/night/night_diffuse.h) plus the
// resolved stars', about 1e-3 lux at a dark site (Roach & Gordon 1973), not the nothing the
// sunlit and moonlit sky alone would give.
TEST(ClientLight, MoonlessNightAmbientIsTheNightsOwnLight) {
  const SkyState s = nightOverTheAlps({2026, 12, 9, 22 * 3600.0});
  ASSERT_TRUE(s.ephemeris);
  ASSERT_LT(s.sunAltitude, -18.0 * kDeg);
  const ClientLight light = clientLight(s, model().get());
  const glm::dvec3 diffuse = night::nightDiffuseIlluminance(*s.ephemeris, s.extinction);
  const glm::dvec3 stars = s.starField ? night::horizontalIlluminance(*s.starField) : glm::dvec3(0.0);
  const double expected = luminance(diffuse + stars);
  std::printf("moonless night: ambient %.3g lux (diffuse night %.3g, stars %.3g), moon %.3g lux\n",
              light.ambientHorizontalLux, luminance(diffuse), luminance(stars), light.moon.horizontalLux);
  EXPECT_GT(light.ambientHorizontalLux, 3e-4);
  EXPECT_LT(light.ambientHorizontalLux, 3e-3);
  // The moonlit sky, if the moon is up at all, adds to it; the night's own light is the floor.
  EXPECT_GT(light.ambientHorizontalLux, 0.95 * expected);
  EXPECT_LT(light.ambientHorizontalLux, 1.05 * expected + 0.1 * light.moon.horizontalLux);
}

// One moon: the first quarter and the crescent against the full moon are the measured moon's
// (Krisciunas & Schaefer 1991, eq. 20: m(phi) = -12.73 + 0.026 |phi| + 4e-9 phi^4, phi in
// degrees; a quarter moon 0.091 of the full, not the smooth Lommel-Seeliger sphere's 0.377), at
// each night's distance (1 / d^2), in every place that tells the moon's light: the ephemeris'
// irradiance, the rendered disc's integral (above the air), the light a client gets (after the
// air: its luminance transmittance divided out) and the goggle's NVIS irradiance of that light
// (class A, after the air, its transmittance in the goggle's band divided out).
// Within 5% of the measured ratios; the earthshine on the dark part adds < 1% at 127 degrees.
TEST(ClientLight, QuarterAndCrescentMoonsAreTheMeasuredMoonEverywhere) {
  struct Night {
    ephemeris::UtcTime utc;
    double phaseDeg, lightQuery = 0.0, disc = 0.0, ephemerisWm2 = 0.0, nvis = 0.0, measured = 0.0;
  };
  std::vector<Night> nights = {{{2027, 1, 22, 23 * 3600.0}, 0.0},  // full (phase 6.6 deg)
                               {{2027, 1, 15, 18 * 3600.0}, 0.0},  // first quarter (91.5)
                               {{2027, 1, 13, 17 * 3600.0}, 0.0},  // crescent (115.8)
                               {{2027, 1, 12, 17 * 3600.0}, 0.0}};  // crescent (127.3)
  for (Night& n : nights) {
    const SkyState s = nightOverTheAlps(n.utc);
    ASSERT_TRUE(s.moonDisc && s.extinction);
    const ephemeris::MoonState& moon = s.ephemeris->moon;
    ASSERT_GT(moon.altitudeRad, 25.0 * kDeg);
    n.phaseDeg = moon.phaseAngleRad / kDeg;
    const double transmittance = luminance(s.extinction->rec709(moon.altitudeRad));
    n.lightQuery = clientLight(s, model().get()).moon.normalLux / transmittance;
    n.disc = luminance(s.moonDisc->irradianceRec709);
    n.ephemerisWm2 = moon.irradianceWm2;
    // The NVIS irradiance of the moon after the air, over the air's transmittance in the
    // goggle's band (the moon's own light with and without the air: the redder light low down
    // passes better there, +6% at 31 degrees against 59), to the moon's normal.
    const double lux = moonIlluminanceLux(s);
    const double nvisTransmittance = nvis::moonIrradiance(lux, s.extinction.get(), s.moonDirection).nvis.a /
                                     nvis::moonIrradiance(lux, nullptr, s.moonDirection).nvis.a;
    n.nvis = nvis::moonIrradiance(lux, s.extinction.get(), s.moonDirection).nvis.a /
             (nvisTransmittance * transmittance * s.moonDisc->centreSeen.z);
    const double m = 0.026 * n.phaseDeg + 4e-9 * std::pow(n.phaseDeg, 4.0);
    n.measured = std::pow(10.0, -0.4 * m) / (moon.distanceKm * moon.distanceKm);
  }
  for (std::size_t i = 1; i < nights.size(); ++i) {
    const Night &n = nights[i], &full = nights[0];
    const double measured = n.measured / full.measured;
    std::printf("phase %.1f deg: measured %.4f of full; ephemeris %.4f, disc %.4f, light query %.4f, NVIS %.4f\n",
                n.phaseDeg, measured, n.ephemerisWm2 / full.ephemerisWm2, n.disc / full.disc,
                n.lightQuery / full.lightQuery, n.nvis / full.nvis);
    EXPECT_NEAR(n.ephemerisWm2 / full.ephemerisWm2 / measured, 1.0, 0.05) << n.phaseDeg;
    EXPECT_NEAR(n.disc / full.disc / measured, 1.0, 0.05) << n.phaseDeg;
    EXPECT_NEAR(n.lightQuery / full.lightQuery / measured, 1.0, 0.05) << n.phaseDeg;
    EXPECT_NEAR(n.nvis / full.nvis / measured, 1.0, 0.05) << n.phaseDeg;
  }
}
