// Refraction, planetary magnitudes and the night-sky irradiances of Wang, Ji & Zhang 2011
// (eq. 9-12, after Jensen et al. 2001).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "ephemeris/night_irradiance.h"
#include "ephemeris/planet_magnitude.h"
#include "ephemeris/refraction.h"
#include "ephemeris/vec3.h"

using namespace skyig::ephemeris;

namespace {
double refrArcmin(double altDeg, double p = 1010.0, double t = 10.0) {
  return refractionSaemundsson(altDeg * kDegToRad, p, t) / kDegToRad * 60.0;
}
}  // namespace

TEST(Refraction, StandardValues) {
  EXPECT_NEAR(refrArcmin(90.0), 0.0, 1e-9);    // none at the zenith
  EXPECT_NEAR(refrArcmin(45.0), 0.99, 0.03);   // ~1 arcmin at 45 degrees
  // A body whose true altitude is -34.5' appears on the horizon (the classic 34' of horizon refraction).
  EXPECT_NEAR(refrArcmin(-34.5 / 60.0), 34.5, 0.3);
}

TEST(Refraction, ConsistentWithBennettsInverseFormula) {
  // Bennett (1982; Meeus eq. 16.3) gives the refraction from the apparent altitude a:
  // R = 1 / tan(a + 7.31 / (a + 4.4)) arcmin. Saemundsson's formula was built as its inverse;
  // Meeus quotes agreement to about 0.1 arcmin (0.07' at the horizon).
  for (double h = -0.5; h <= 89.0; h += 0.5) {
    const double r = refrArcmin(h);
    const double a = h + r / 60.0;
    const double bennett = 1.0 / std::tan((a + 7.31 / (a + 4.4)) * kDegToRad);
    EXPECT_NEAR(r, bennett, 0.1) << h;
  }
}

TEST(Refraction, ScalesWithPressureAndTemperatureAndIsMonotonic) {
  EXPECT_NEAR(refrArcmin(5.0, 505.0), 0.5 * refrArcmin(5.0), 1e-9);
  EXPECT_NEAR(refrArcmin(5.0, 1010.0, -10.0), refrArcmin(5.0) * 283.0 / 263.0, 1e-9);
  EXPECT_DOUBLE_EQ(refrArcmin(5.0, 0.0), 0.0);  // vacuum
  double lastApparent = -1e9;
  for (double h = -10.0; h <= 90.0; h += 0.01) {
    const double apparent = h + refrArcmin(h) / 60.0;
    ASSERT_GT(apparent, lastApparent) << h;
    lastApparent = apparent;
  }
  // Below -2 degrees it fades linearly to nothing at -5 degrees.
  EXPECT_NEAR(refrArcmin(-3.5), 0.5 * refrArcmin(-2.0), 1e-9);
  EXPECT_DOUBLE_EQ(refrArcmin(-5.0), 0.0);
  EXPECT_DOUBLE_EQ(refrArcmin(-30.0), 0.0);
}

TEST(Refraction, RejectsBadInput) {
  EXPECT_THROW(refractionSaemundsson(std::nan(""), 1010.0, 10.0), std::invalid_argument);
  EXPECT_THROW(refractionSaemundsson(0.1, -1.0, 10.0), std::invalid_argument);
  EXPECT_THROW(refractionSaemundsson(0.1, 1010.0, -300.0), std::invalid_argument);
}

TEST(PlanetMagnitude, KnownAppearances) {
  // Jupiter at opposition, r = 4.95 au, delta = 3.95 au: -9.395 + 5 log10(19.55) = -2.94.
  EXPECT_NEAR(planetMagnitude(Planet::Jupiter, 4.95, 3.95, 0.0), -2.94, 0.01);
  // Venus near greatest brilliancy (r 0.723, delta 0.43, alpha 120 deg) is about -4.7.
  EXPECT_NEAR(planetMagnitude(Planet::Venus, 0.723, 0.43, 120.0 * kDegToRad), -4.7, 0.2);
  // Mars at the perihelic opposition of 2003 August (r 1.381, delta 0.373, phase angle 6 deg): -2.9.
  EXPECT_NEAR(planetMagnitude(Planet::Mars, 1.381, 0.373, 6.0 * kDegToRad), -2.9, 0.1);
  // Saturn's rings brighten it: wide open (26.7 deg) versus edge-on at the same distances.
  const double open = planetMagnitude(Planet::Saturn, 9.5, 8.5, 0.0, 26.7 * kDegToRad);
  const double edge = planetMagnitude(Planet::Saturn, 9.5, 8.5, 0.0, 0.0);
  EXPECT_NEAR(edge - open, 1.825 * std::sin(26.7 * kDegToRad) + 0.378 * std::sin(26.7 * kDegToRad), 1e-9);
  // Mercury is fainter at larger phase angles.
  EXPECT_GT(planetMagnitude(Planet::Mercury, 0.4, 1.0, 100.0 * kDegToRad),
            planetMagnitude(Planet::Mercury, 0.4, 1.0, 20.0 * kDegToRad));
}

TEST(NightIrradiance, MagnitudeConversionsEq10And11) {
  // Corrected eq. 11: the sun at m = -26.7 gives about 1.2e3 W/m^2 (the solar constant's order).
  EXPECT_NEAR(irradianceFromMagnitude(-26.7), 1.2e3, 0.05e3);
  EXPECT_NEAR(irradianceFromMagnitude(0.0), 2.512e-8, 0.001e-8);  // 10^-7.6 W/m^2 for magnitude 0
  for (double m : {-12.7, -4.0, 0.0, 6.5}) EXPECT_NEAR(magnitudeFromIrradiance(irradianceFromMagnitude(m)), m, 1e-12);
  // Five magnitudes are a factor 100.
  EXPECT_NEAR(irradianceFromMagnitude(1.0) / irradianceFromMagnitude(6.0), 100.0, 1e-9);
}

TEST(NightIrradiance, ColourTemperatureEq12) {
  EXPECT_NEAR(colourTemperatureFromBv(0.65), 5785.1, 0.1);  // the sun: close to its 5772 K
  EXPECT_NEAR(colourTemperatureFromBv(0.0), 12500.0, 1e-9);
  EXPECT_THROW(colourTemperatureFromBv(-0.56), std::invalid_argument);
  EXPECT_THROW(colourTemperatureFromBv(std::nan("")), std::invalid_argument);
}

TEST(NightIrradiance, MoonEq9) {
  // Phase law: 1 at full, 0 at new, decreasing.
  EXPECT_DOUBLE_EQ(lunarPhaseLaw(0.0), 1.0);
  EXPECT_NEAR(lunarPhaseLaw(kPi), 0.0, 1e-12);
  double last = 2.0;
  for (double phi = 0.0; phi <= kPi; phi += 0.01) {
    const double f = lunarPhaseLaw(phi);
    ASSERT_LT(f, last) << phi;
    last = f;
  }
  // Full moon at the mean distance, sun-moon distance 1 au: the measured moon's V = -12.73
  // (Krisciunas & Schaefer 1991) through eq. 11, 10^(-(19 - 12.73) / 2.5) = 3.105e-3 W/m^2, 2.33
  // times eq. 9's 2/3 * 0.072 * (1737.4/384400)^2 * 1361 = 1.335e-3 (a smooth sphere has no
  // opposition surge); the earthshine vanishes at full moon (the earth's phase law at pi).
  const double full = moonIrradiance(0.0, 384400.0, kAuKm);
  EXPECT_NEAR(full, std::pow(10.0, -(19.0 - 12.73) / 2.5), 1e-12);
  EXPECT_NEAR(lunarOppositionFactor(0.0), full / (2.0 / 3.0 * 0.072 * std::pow(1737.4 / 384400.0, 2) * 1361.0), 1e-12);
  // First quarter: Krisciunas & Schaefer's 0.026 x 90 + 4e-9 x 90^4 = 2.60 magnitudes below full,
  // 0.0911 of it, where the smooth sphere's law keeps 0.377.
  EXPECT_NEAR(lunarPhaseFunction(kPi / 2), std::pow(10.0, -0.4 * (2.34 + 4e-9 * std::pow(90.0, 4))), 1e-12);
  EXPECT_NEAR(moonIrradiance(kPi / 2, 384400.0, kAuKm) / full, 0.0911, 0.002);  // plus a little earthshine
  // Inverse square with distance.
  EXPECT_NEAR(moonIrradiance(0.3, 363300.0, kAuKm) / moonIrradiance(0.3, 405500.0, kAuKm),
              std::pow(405500.0 / 363300.0, 2), 1e-3);
  // Quarter moon: 1 - sin(45) tan(45) ln(cot(22.5)) = 1 - ln(1 + sqrt 2) / sqrt 2 = 0.3768.
  EXPECT_NEAR(lunarPhaseLaw(kPi / 2), 1.0 - std::log(1.0 + std::sqrt(2.0)) / std::sqrt(2.0), 1e-12);
}
