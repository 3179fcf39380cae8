// The public entry point: behaviours, geometry and bad input.
#include "ephemeris/ephemeris.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "ephemeris/ephemeris_cache.h"

using namespace skyig::ephemeris;

namespace {
Observer place(double latDeg, double lonDeg, double heightM = 0.0) {
  Observer o;
  o.latitudeRad = latDeg * kDegToRad;
  o.longitudeRad = lonDeg * kDegToRad;
  o.heightM = heightM;
  return o;
}

void expectInvalid(const UtcTime& t, const Observer& o, const std::string& mention) {
  try {
    computeEphemeris(t, o);
    FAIL() << "accepted: " << mention;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(mention), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(Ephemeris, RejectsBadInputNamingTheValue) {
  const UtcTime t{2024, 6, 21, 43200.0};
  expectInvalid(t, place(91.0, 0.0), "latitude 91");
  expectInvalid(t, place(-90.5, 0.0), "latitude -90.5");
  expectInvalid(t, place(std::nan(""), 0.0), "latitude nan");
  expectInvalid(t, place(10.0, INFINITY), "longitude inf");
  expectInvalid(t, place(10.0, 0.0, 2e5), "height 200000");
  expectInvalid(UtcTime{2101, 1, 1, 0.0}, place(10.0, 0.0), "2101");
  expectInvalid(UtcTime{1899, 12, 31, 0.0}, place(10.0, 0.0), "1899");
  expectInvalid(UtcTime{2023, 2, 29, 0.0}, place(10.0, 0.0), "day 29");
  Observer o = place(10.0, 0.0);
  o.pressureHpa = -5.0;
  expectInvalid(t, o, "pressure -5");
  EXPECT_NO_THROW(computeEphemeris(t, place(90.0, 0.0)));
  EXPECT_NO_THROW(computeEphemeris(t, place(-90.0, 0.0)));
}

TEST(Ephemeris, SunAtSolsticeNoonAndThePole) {
  // 2024 June 20 20:51 UTC solstice: the sun's declination is +23.44 degrees.
  const SkyEphemeris s = computeEphemeris(UtcTime{2024, 6, 20, 20 * 3600.0 + 51 * 60.0}, place(0.0, 0.0));
  EXPECT_NEAR(s.sun.declinationRad / kDegToRad, 23.44, 0.01);
  // At the north pole the altitude of the sun equals its declination (up to 8.8" of parallax).
  const SkyEphemeris pole = computeEphemeris(UtcTime{2024, 6, 20, 20 * 3600.0 + 51 * 60.0}, place(90.0, 0.0));
  EXPECT_NEAR(pole.sun.altitudeRad, pole.sun.declinationRad, 1e-4);
  // Near local apparent noon at Greenwich the sun is due south at 90 - 51.48 + 23.44 degrees.
  const SkyEphemeris g = computeEphemeris(UtcTime{2024, 6, 21, 12 * 3600.0 + 1 * 60.0 + 50.0}, place(51.48, 0.0));
  EXPECT_NEAR(g.sun.azimuthRad / kDegToRad, 180.0, 0.2);
  EXPECT_NEAR(g.sun.altitudeRad / kDegToRad, 90.0 - 51.48 + 23.43, 0.02);
  EXPECT_GT(g.sun.altitudeRefractedRad, g.sun.altitudeRad);
  EXPECT_NEAR(g.sun.angularRadiusRad / kDegToRad * 60.0, 15.75, 0.05);  // aphelion-season sun
}

TEST(Ephemeris, MoonParallaxAndTopocentricDistance) {
  // Seen from the equator with the moon on the horizon, the moon is lower than from the
  // geocentre by its horizontal parallax (~57'), and about one earth radius farther.
  const UtcTime t{2024, 3, 10, 0.0};
  for (double lon = 0.0; lon < 360.0; lon += 7.5) {
    const SkyEphemeris s = computeEphemeris(t, place(0.0, lon));
    if (std::fabs(s.moon.altitudeRad) > 0.02) continue;
    const ApparentPlace geo = apparentGeocentricPlace(Body::Moon, s.time.jdTt);
    const double parallax = std::asin(6378.137 / geo.distanceKm);
    const double shift = angleBetween(
        Vec3{std::cos(s.moon.declinationRad) * std::cos(s.moon.rightAscensionRad),
             std::cos(s.moon.declinationRad) * std::sin(s.moon.rightAscensionRad), std::sin(s.moon.declinationRad)},
        Vec3{std::cos(geo.declinationRad) * std::cos(geo.rightAscensionRad),
             std::cos(geo.declinationRad) * std::sin(geo.rightAscensionRad), std::sin(geo.declinationRad)});
    EXPECT_NEAR(shift, parallax, 0.02 * parallax);
    EXPECT_NEAR(s.moon.distanceKm - geo.distanceKm, 0.0, 200.0);  // on the horizon: nearly tangent
    return;
  }
  FAIL() << "no longitude with the moon on the horizon";
}

TEST(Ephemeris, StarMatrixIsARotationAndMatchesTheCpuPath) {
  const SkyEphemeris s = computeEphemeris(UtcTime{2031, 11, 5, 7200.0}, place(47.0, 8.0, 500.0));
  const Mat3 p = s.j2000ToEnu * transposed(s.j2000ToEnu);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(p.m[static_cast<std::size_t>(3 * i + j)], i == j ? 1.0 : 0.0, 1e-14);
  // Annual aberration is at most 20.5" (plus 0.3" diurnal).
  EXPECT_LT(norm(s.aberrationJ2000) / kArcsecToRad, 21.0);
  EXPECT_GT(norm(s.aberrationJ2000) / kArcsecToRad, 20.0);
  // Polaris (HR 424) stands at about the latitude (within its 0.7 degree polar distance).
  Star polaris;
  polaris.hr = 424;
  polaris.raRad = (2 + 31 / 60.0 + 49.09 / 3600.0) * 15.0 * kDegToRad;
  polaris.decRad = (89 + 15 / 60.0 + 51.0 / 3600.0) * kDegToRad;
  polaris.directionJ2000 = {std::cos(polaris.decRad) * std::cos(polaris.raRad),
                            std::cos(polaris.decRad) * std::sin(polaris.raRad), std::sin(polaris.decRad)};
  const BodyPosition pp = starPosition(polaris, s);
  EXPECT_NEAR(pp.altitudeRad / kDegToRad, 47.0, 0.8);
  EXPECT_LT(std::fabs(std::remainder(pp.azimuthRad, kTwoPi)) / kDegToRad, 1.2);
  // The CPU path equals the renderer's recipe: M * normalize(u + beta).
  const Vec3 gpu = s.j2000ToEnu * normalized(starDirectionAt(polaris, s.time.jdTt) + s.aberrationJ2000);
  EXPECT_LT(angleBetween(gpu, pp.enu), 1.5e-8);  // 3 mas: they differ in the (v/c)^2 terms
}

TEST(Ephemeris, BrightLimbPointsTowardsTheSunInTheObserversView) {
  // Independent check by vector geometry: the bright limb's midpoint lies on the great circle
  // from the moon towards the sun. In the view towards the moon (up = towards the zenith, left =
  // up x forward) that direction's angle from "up", counterclockwise, is the bright-limb angle.
  for (int day = 0; day < 28; day += 3) {
    const SkyEphemeris s = computeEphemeris(UtcTime{2027, 3, 1 + day, 64800.0}, place(40.0, -3.7));
    const Vec3 m = s.moon.enu, sun = s.sun.enu, zenith{0.0, 0.0, 1.0};
    const Vec3 up = normalized(zenith - dot(zenith, m) * m);
    const Vec3 left = cross(up, m);
    const Vec3 toSun = sun - dot(sun, m) * m;
    const double expected = wrapTwoPi(std::atan2(dot(toSun, left), dot(toSun, up)));
    EXPECT_NEAR(std::remainder(s.moon.brightLimbAngleRad - expected, kTwoPi), 0.0, 0.1 * kDegToRad) << day;
  }
}

TEST(Ephemeris, PlanetsHaveSensibleMagnitudesAndPhases) {
  const SkyEphemeris s = computeEphemeris(UtcTime{2025, 1, 10, 0.0}, place(0.0, 0.0));
  // Venus near greatest eastern elongation (10 Jan 2025): about half lit, magnitude about -4.6.
  EXPECT_STREQ(s.planets[1].name, "Venus");
  EXPECT_NEAR(s.planets[1].illuminatedFraction, 0.5, 0.05);
  EXPECT_NEAR(s.planets[1].magnitude, -4.6, 0.2);
  // Mars at opposition (16 Jan 2025): full and about -1.4.
  EXPECT_NEAR(s.planets[2].illuminatedFraction, 1.0, 0.01);
  EXPECT_NEAR(s.planets[2].magnitude, -1.4, 0.2);
  for (const PlanetState& p : s.planets) {
    EXPECT_GT(p.irradianceWm2, 0.0);
    EXPECT_LT(p.phaseAngleRad, kPi);
  }
}

TEST(Ephemeris, CacheMatchesDirectEvaluation) {
  EphemerisCache cache;
  const Observer o = place(-33.9, 151.2, 50.0);
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const UtcTime t{2040, 2, 1 + i / 10, 400.0 * i + 17.0};
    const SkyEphemeris a = cache.compute(t, o), b = computeEphemeris(t, o);
    worst = std::max(worst, angleBetween(a.moon.enu, b.moon.enu));
    worst = std::max(worst, angleBetween(a.sun.enu, b.sun.enu));
    for (std::size_t p = 0; p < 5; ++p) worst = std::max(worst, angleBetween(a.planets[p].enu, b.planets[p].enu));
    EXPECT_NEAR(a.gastRad, b.gastRad, 1e-12);
  }
  EXPECT_LT(worst / kArcsecToRad, 0.001);
  // 60 frames a second for ten minutes cross a node at most once... plus the first four nodes.
  EphemerisCache frames;
  for (int i = 0; i < 36000; ++i) frames.compute(UtcTime{2040, 2, 1, 100.0 + i / 60.0}, o);
  EXPECT_LE(frames.evaluations(), 5u);
}
