// Spectral data, the medium's coefficients, colour conversion and run-time conditions against
// published values and closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/atmosphere/conditions.h"
#include "physics/spectrum/spectral_data.h"
#include "physics/spectrum/spectrum.h"

namespace skyig::atmosphere {
namespace {

TEST(AtmosphereSpectral, ScatteringCoefficientsAreThoseOfBrunetons2017Earth) {
  const Medium m;
  // Bruneton's 2017 reference implementation (demo.cc, the Earth's atmosphere): Rayleigh
  // 1.24062e-6 / lambda^4 (lambda in um), i.e. 5.802, 13.558, 33.100 e-6 m^-1 at 680 / 550 /
  // 440 nm; Mie 3.996e-6 m^-1 scattering, 4.44e-6 m^-1 extinction.
  EXPECT_NEAR(coefficientsAt(m, 680.0).rayleighScattering, 5.802e-6, 0.001e-6);
  EXPECT_NEAR(coefficientsAt(m, 550.0).rayleighScattering, 13.558e-6, 0.001e-6);
  EXPECT_NEAR(coefficientsAt(m, 440.0).rayleighScattering, 33.100e-6, 0.001e-6);
  EXPECT_NEAR(coefficientsAt(m, 550.0).mieScattering, 3.996e-6, 1e-12);
  EXPECT_NEAR(coefficientsAt(m, 440.0).mieExtinction, 4.44e-6, 1e-12);
}

TEST(AtmosphereSpectral, OzoneColumnIsThreeHundredDobson) {
  const Medium m;
  // Column = peak density x half width of the tent (integral of the profile).
  EXPECT_NEAR(ozonePeakNumberDensity(m) * m.ozoneHalfWidthM / kDobsonUnitPerM2, 300.0, 1e-9);
  // Chappuis band: absorbs more at 600 nm than at 440 or 680 nm.
  EXPECT_GT(ozoneCrossSection(600.0), ozoneCrossSection(440.0));
  EXPECT_GT(ozoneCrossSection(600.0), ozoneCrossSection(680.0));
}

TEST(AtmosphereSpectral, ColourMatchingFunctionIntegrals) {
  // Integral of ybar over 360-830 nm = 106.857 (CIE 1931, 1 nm data); x and z integrals are
  // equal to it within 0.1% by construction of the equal-energy white point.
  glm::dvec3 sum(0.0);
  for (double w = 360.0; w <= 830.0; w += 1.0) sum += cie1931ColourMatching(w);
  EXPECT_NEAR(sum.y, 106.857, 0.15);
  EXPECT_NEAR(sum.x / sum.y, 1.0, 0.002);
  EXPECT_NEAR(sum.z / sum.y, 1.0, 0.002);
  EXPECT_DOUBLE_EQ(cie1931ColourMatching(555.0).y, 1.0);
  EXPECT_THROW(cie1931ColourMatching(300.0), std::out_of_range);
}

TEST(AtmosphereSpectral, D65WhiteIsRec709White) {
  const glm::dvec3 rgb = xyzToRec709({0.95047, 1.0, 1.08883});
  EXPECT_NEAR(rgb.r, 1.0, 1e-4);
  EXPECT_NEAR(rgb.g, 1.0, 1e-4);
  EXPECT_NEAR(rgb.b, 1.0, 1e-4);
}

TEST(AtmosphereSpectral, SunSpectrumConvertsExactlyAtSixteenWavelengths) {
  // The conversion weights fold in the solar fine structure, so the sun's own spectrum gives
  // the luminance of a 1 nm integration of the ASTM table, at 16 samples as at 471.
  std::vector<double> fine;
  for (double w = 360.0; w <= 830.0; w += 1.0) fine.push_back(w);
  const SpectralConverter fineConverter(fine);
  const SpectralConverter coarseConverter(defaultWavelengths());
  auto sun = [](const SpectralConverter& c) {
    std::vector<double> s;
    for (double w : c.wavelengths()) s.push_back(solarIrradiance(w));
    return c.toXyz(s);
  };
  const glm::dvec3 a = sun(fineConverter);
  const glm::dvec3 b = sun(coarseConverter);
  EXPECT_NEAR(b.y / a.y, 1.0, 2e-3);
  EXPECT_NEAR(b.x / a.x, 1.0, 2e-3);
  // Solar illuminance outside the atmosphere, the luminous solar constant: 133.3 klx (Darula,
  // Kittler & Gueymard 2005, from the same ASTM/Gueymard spectrum); 360-830 nm carries
  // nearly all of it.
  EXPECT_NEAR(a.y, 133334.0, 0.02 * 133334.0);
}

TEST(AtmosphereConditions, KoschmiederVisibility) {
  const Medium clear;
  // The default aerosols: beta = 4.44e-6 + 13.558e-6 m^-1 -> V = 3.912 / beta = 217 km.
  EXPECT_NEAR(visibilityOf(clear), 3.912 / (4.44e-6 + 13.558e-6) / 1000.0, 0.01);
  Conditions hazy;
  hazy.visibilityKm = 5.0;
  const Medium m = applyConditions(clear, hazy);
  EXPECT_NEAR(m.mieExtinctionPerM, 3.912 / 5000.0 - 13.558e-6, 1e-9);
  EXPECT_NEAR(visibilityOf(m), 5.0, 1e-9);
  // The added aerosol is water: the absorption stays the medium's, 4.44e-6 x (1 - 0.9) m^-1.
  EXPECT_NEAR(m.mieExtinctionPerM * (1.0 - m.mieSingleScatteringAlbedo), 4.44e-7, 1e-15);
  EXPECT_GT(m.mieSingleScatteringAlbedo, 0.999);
  hazy.visibilityKm = 400.0;  // clearer than clean air allows: clean air, no aerosols
  EXPECT_EQ(applyConditions(clear, hazy).mieExtinctionPerM, 0.0);
  EXPECT_NEAR(visibilityOf(applyConditions(clear, hazy)), cleanAirVisibilityKm(clear), 1e-9);
  for (double bad : {-1.0, 0.0, std::nan(""), HUGE_VAL}) {
    hazy.visibilityKm = bad;
    EXPECT_THROW(applyConditions(clear, hazy), std::invalid_argument) << bad;
  }
}

TEST(AtmosphereConditions, HumidityGrowsTheAerosolsAndAlbedoApplies) {
  const Medium base;
  Conditions wet;
  wet.relativeHumidity = 0.9;
  const Medium m = applyConditions(base, wet);
  // ((1 - 0.9) / (1 - 0.5))^-0.25 = 5^0.25.
  EXPECT_NEAR(m.mieExtinctionPerM / base.mieExtinctionPerM, std::pow(5.0, 0.25), 1e-12);
  wet.relativeHumidity = 0.5;
  EXPECT_DOUBLE_EQ(applyConditions(base, wet).mieExtinctionPerM, base.mieExtinctionPerM);
  wet.relativeHumidity = 1.0;
  EXPECT_THROW(applyConditions(base, wet), std::invalid_argument);
  Conditions snow;
  snow.groundAlbedo = 0.8;
  EXPECT_DOUBLE_EQ(applyConditions(base, snow).groundAlbedo, 0.8);
  snow.groundAlbedo = 1.5;
  EXPECT_THROW(applyConditions(base, snow), std::invalid_argument);
}

}  // namespace
}  // namespace skyig::atmosphere
