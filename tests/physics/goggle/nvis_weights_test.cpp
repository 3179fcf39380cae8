// The goggle channel's weights (sky/nvis_weights.h) and the image intensifier's physics
// (physics/goggle/intensifier.glsl, compiled as C++), on the CPU.
#include "physics/goggle/goggle_physics.h"
#include "physics/goggle/night_spectra.h"
#include "sky/nvis_weights.h"
#include "sky/sky_state.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

using namespace skyig;
using namespace skyig::sky;

namespace {

using skyig::kDeg;

SkyState dusk(double sunAltitudeDeg) {
  ObserverState o;
  o.utc = {2026, 1, 3, 20.0 * 3600.0};
  return buildSkyState(o, SkyConditions{}, SunOverride{270.0 * kDeg, sunAltitudeDeg * kDeg});
}

}  // namespace

// The table the star pass weighs each star with is Planck's integral to within 0.1%, between
// its nodes too, in both classes.
TEST(NvisWeights, BlackbodyTableIsThePlanckIntegral) {
  const nvis::Transmittance unit = nvis::unitTransmittance();
  for (double t : {1700.0, 2905.0, 3600.0, 5777.0, 9602.0, 13208.0, 31000.0}) {
    const nvis::NvisRadiance exact = nvis::nvisFromLuminance(nvis::blackbodySpectrum(t), unit, 1.0);
    EXPECT_NEAR(nvisPerLuxOfBlackbody(t, nvis::NvisClass::A), exact.a, 1e-3 * exact.a) << t << " K";
    EXPECT_NEAR(nvisPerLuxOfBlackbody(t, nvis::NvisClass::B), exact.b, 1e-3 * exact.b) << t << " K";
  }
  EXPECT_THROW(nvisPerLuxOfBlackbody(std::nan(""), nvis::NvisClass::A), std::invalid_argument);
}

// In the eye's band nothing is weighted: the passes draw their colour as before.
TEST(NvisWeights, TheEyesBandLeavesEveryLightAsItIs) {
  const NvisWeights w = nvisWeights(SpectralBand::Visible, dusk(-20.0), glm::dvec3(0.0, 1.0, 0.3));
  EXPECT_FALSE(w.nvis);
  for (double k : {w.sunlitSky, w.sunDisc, w.moonlitSky, w.moon, w.airglow, w.zodiacal, w.milkyWay, w.nightGround})
    EXPECT_EQ(k, 1.0);
}

// Per cd/m^2, the goggle sees more of the redder lights: the moon's disc overhead than the blue
// sky it lights (Rayleigh scattering moves light to the blue), the airglow (OH bands in the near
// infrared) more than the zodiacal light (sunlight, slightly reddened), the moon and the sun low
// in the sky (reddened by the air) more than high. Class B's filter cuts more of the visible, so
// every light's weight falls from A to B.
TEST(NvisWeights, RedderLightsWeighMoreInTheGogglesBand) {
  SkyState high = dusk(40.0), low = dusk(2.0);
  high.moonDirection = glm::dvec3(0.0, 0.0, 1.0);
  low.moonDirection = glm::normalize(glm::dvec3(0.0, 1.0, 0.035));
  const glm::dvec3 view(0.0, 1.0, 0.5);
  const NvisWeights a = nvisWeights(SpectralBand::NvisClassA, high, view);
  const NvisWeights b = nvisWeights(SpectralBand::NvisClassB, high, view);
  ASSERT_TRUE(a.nvis);
  EXPECT_GT(a.moon, 1.5 * a.moonlitSky);
  EXPECT_GT(a.airglow, 2.0 * a.zodiacal);
  EXPECT_GT(nvisWeights(SpectralBand::NvisClassA, low, view).moon, 1.2 * a.moon);
  EXPECT_GT(nvisWeights(SpectralBand::NvisClassA, low, view).sunDisc, 1.2 * a.sunDisc);
  for (auto [ka, kb] : {std::pair{a.sunlitSky, b.sunlitSky}, {a.moon, b.moon}, {a.airglow, b.airglow}}) EXPECT_LT(kb, ka);
  std::cout << "class A, W m^-2 sr^-1 per cd/m^2: sunlit sky " << a.sunlitSky << ", moonlit sky " << a.moonlitSky
            << ", moon " << a.moon << ", airglow " << a.airglow << ", zodiacal " << a.zodiacal << ", Milky Way "
            << a.milkyWay << "; illuminant A " << nvisPerLuxOfBlackbody(2856.0, nvis::NvisClass::A) << "\n";
}

// The tube standards' signal-to-noise test: a 0.2 mm spot at 108 microlux of illuminant A
// through a 10 Hz bandwidth. The Omni contracts' third-generation tubes are specified at 21
// (Omni IV-V, whose 1800 uA/lm the model has) to 28 (Omni VII); the model gives 30.9, the
// closed form sqrt(S E A t / (e F)), within 30% of that range.
TEST(GogglePhysics, SignalToNoiseAtTheStandardsLevelIsAThirdGenerationTubes) {
  const double snr = shader::goggleSignalToNoise(108e-6);
  const double area = std::numbers::pi * 1e-4 * 1e-4;
  const double closedForm = std::sqrt(1.8e-3 * 108e-6 * area * 0.05 / (1.602176634e-19 * 2.0));
  EXPECT_NEAR(snr, closedForm, 1e-9 * closedForm);
  EXPECT_GE(snr, 21.0);
  EXPECT_LE(snr, 36.0);
  RecordProperty("snr", std::to_string(snr));
  std::cout << "signal-to-noise at 108 microlux: " << snr << "\n";
}

// The tube's gain in SI: 50000 fL/fc is 15915 (cd/m^2) per lux (1 fL = 1/pi cd/ft^2, 1 fc =
// 1 lm/ft^2: the ratio is 1/pi); a manual gain is its fraction, clamped to the tube's range.
// The automatic control's gain is the GPU's (GogglePassGl.AutomaticBrightness...).
TEST(GogglePhysics, ManualGainIsItsShareOfFiftyThousandFootLambertsPerFootCandle) {
  EXPECT_NEAR(shader::kMaxLuminanceGain, 50000.0 / std::numbers::pi, 1e-3);
  EXPECT_DOUBLE_EQ(shader::manualGain(0.25), 0.25 * shader::kMaxLuminanceGain);
  EXPECT_DOUBLE_EQ(shader::manualGain(1.5), shader::kMaxLuminanceGain);
  EXPECT_DOUBLE_EQ(shader::manualGain(-1.0), 0.0);
}
