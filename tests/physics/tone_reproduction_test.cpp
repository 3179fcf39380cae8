// Tone reproduction (Wang, Ji & Zhang 2011, eq. 13-21, after Tumblin & Rushmeier 1993 and
// Larson et al. 1997) against hand computations from the printed formulas.
#include "physics/physics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig;

namespace {
constexpr double kLambert = std::numbers::pi * 1e-4;

// Wang, Ji & Zhang 2011, eq. 14 as printed, La in cd/m^2 (with +0.218: see
// tumblin_rushmeier.glsl).
double paperAlpha(double la) { return 0.4 * std::log10(la) + 1.519; }
double paperBeta(double la) { return -0.4 * std::pow(std::log10(la), 2) + 0.218 * std::log10(la) + 6.1642; }

// Eq. 19 written out with the paper's alpha and beta.
double paperEq19(double lw, double lwa, double lda, double ldmax, double lamb, double gamma) {
  const double ld = std::pow(10.0, (paperBeta(lwa) - paperBeta(lda)) / paperAlpha(lda)) *
                    std::pow(kLambert * lw, paperAlpha(lwa) / paperAlpha(lda)) / kLambert;
  return std::pow(std::clamp((ld - lamb) / ldmax, 0.0, 1.0), 1.0 / gamma);
}
}  // namespace

// The original lambert constants (2.92, -2.584, 2.0208) are eq. 14 in cd/m^2, to the rounding
// of the published four- and five-digit constants.
TEST(TumblinRushmeier, OriginalConstantsEqualPaperFormInCandela) {
  for (double la : {1e-2, 0.5, 10.0, 300.0, 8000.0}) {
    EXPECT_NEAR(shader::trAlpha(la), paperAlpha(la), 2e-4) << la;
    EXPECT_NEAR(shader::trBeta(la), paperBeta(la), 2e-3) << la;
  }
}

TEST(TumblinRushmeier, Eq19HandValues) {
  // A daylight sky seen on a 100 cd/m^2 projector, viewer adapted to 10 cd/m^2.
  const shader::DisplayModel display{100.0, 0.1, 2.2, 10.0};
  for (double lw : {500.0, 4000.0, 9000.0}) {
    const double ld = shader::tumblinRushmeierDisplayLuminance(lw, 4000.0, 10.0);
    const double n = shader::displayValue(ld, display.ambientLuminance, display.maxLuminance, display.gamma);
    EXPECT_NEAR(n, paperEq19(lw, 4000.0, 10.0, 100.0, 0.1, 2.2), 1e-3) << lw;
  }
  // By hand: Lw = Lwa = 4000 cd/m^2, Lda = 10 -> alpha_w = 2.9598, beta_w = 1.7595,
  // alpha_d = 1.9190, beta_d = 5.9822: Ld = 10^(-2.2005) 1.2566^1.5424 / (pi 1e-4) = 28.54 cd/m^2.
  EXPECT_NEAR(shader::tumblinRushmeierDisplayLuminance(4000.0, 4000.0, 10.0), 28.54, 0.05);
}

TEST(TumblinRushmeier, MonotonicAndBrighterWorldLooksBrighter) {
  double previous = 0.0;
  for (double lw = 1e-3; lw < 1e5; lw *= 1.5) {
    const double ld = shader::tumblinRushmeierDisplayLuminance(lw, 100.0, 10.0);
    EXPECT_GT(ld, previous);
    previous = ld;
  }
  // The same relative scene shown at night looks darker than by day (absolute brightness).
  EXPECT_LT(shader::tumblinRushmeierDisplayLuminance(1e-2, 1e-2, 10.0),
            shader::tumblinRushmeierDisplayLuminance(1e3, 1e3, 10.0));
}

TEST(DisplayModel, Eq18InvertsEq17) {
  // L_d = L_amb + L_dmax n^gamma.
  for (double n : {0.1, 0.5, 0.9}) {
    const double ld = 0.5 + 80.0 * std::pow(n, 2.4);
    EXPECT_NEAR(shader::displayValue(ld, 0.5, 80.0, 2.4), n, 1e-12);
  }
  EXPECT_EQ(shader::displayValue(1e6, 0.5, 80.0, 2.4), 1.0);
  EXPECT_EQ(shader::displayValue(0.1, 0.5, 80.0, 2.4), 0.0);
}

// Larson et al. 1997: V = Y (1.33 (1 + (Y + Z)/X) - 1.68); for an equal-energy white V = 2.31 Y,
// so eq. 21's 0.4468 V is 1.032 Y: a white field keeps (within 3%) its luminance in rod vision.
TEST(Scotopic, EqualEnergyWhite) {
  EXPECT_NEAR(shader::scotopicLuminance(glm::dvec3(1.0)), 2.31, 1e-12);
  EXPECT_NEAR(0.4468 * shader::scotopicLuminance(glm::dvec3(3.0)), 3.0 * 1.032108, 1e-9);
}

// Eq. 20: s = 0 below 0.01 cd/m^2, 1 above 10^0.6, 0.5 half way in log (10^-0.7).
TEST(Scotopic, MesopicFactorEq20) {
  EXPECT_EQ(shader::mesopicFactor(1e-3), 0.0);
  EXPECT_EQ(shader::mesopicFactor(5.0), 1.0);
  EXPECT_NEAR(shader::mesopicFactor(std::pow(10.0, -0.7)), 0.5, 1e-12);
  const double t = (std::log10(0.1) + 2.0) / 2.6;
  EXPECT_NEAR(shader::mesopicFactor(0.1), 3 * t * t - 2 * t * t * t, 1e-12);
}

// Eq. 21: a saturated red at 1e-3 cd/m^2 becomes rod blue (0.25, 0.25) with Y = 0.4468 V;
// at 100 cd/m^2 it is untouched.
TEST(Scotopic, BlendEq21) {
  const glm::dvec3 redDim = shader::rec709ToXyz(glm::dvec3(1.0, 0.0, 0.0)) / 0.2126729 * 1e-3;
  const glm::dvec3 eye = shader::mesopicxyY(redDim);
  EXPECT_NEAR(eye.x, 0.25, 1e-12);
  EXPECT_NEAR(eye.y, 0.25, 1e-12);
  EXPECT_NEAR(eye.z, 0.4468 * shader::scotopicLuminance(redDim), 1e-15);
  const glm::dvec3 redBright = redDim * 1e5;
  const glm::dvec3 seen = shader::mesopicxyY(redBright);
  const glm::dvec3 xyY = shader::xyzToxyY(redBright);
  EXPECT_NEAR(seen.x, xyY.x, 1e-12);
  EXPECT_NEAR(seen.z, xyY.z, 1e-9);
}

// As light fails, the displayed colour of a sky slides to the rod-vision blue (0.25, 0.25).
TEST(ToneReproduction, DimSkySlidesToRodBlue) {
  const shader::DisplayModel display{100.0, 0.0, 2.2, 10.0};
  auto distanceToRodBlue = [&](double scale) {
    const glm::dvec3 sky = glm::dvec3(0.9, 0.8, 0.5) * scale;  // a warm colour, far from it
    const glm::dvec3 ld = shader::toneReproduceLinear(sky, shader::rec709Luminance(sky), display);
    const glm::dvec3 xyY = shader::xyzToxyY(shader::rec709ToXyz(ld));
    return glm::length(glm::dvec2(xyY.x, xyY.y) - glm::dvec2(0.25, 0.25));
  };
  EXPECT_GT(distanceToRodBlue(1000.0), distanceToRodBlue(0.3));
  EXPECT_GT(distanceToRodBlue(0.3), distanceToRodBlue(0.03));
  EXPECT_LT(distanceToRodBlue(1e-3), 1e-6);
}

// A colour too bright in one channel for the display is desaturated towards white along its
// own hue, keeping its luminance, instead of clipping that channel alone (the cyan fringe of a
// pale-blue horizon).
TEST(ToneReproduction, HighlightsCompressAlongTheirHue) {
  const glm::dvec3 paleBlue(60.0, 95.0, 150.0);  // cd/m^2 (Y = 91.5) on a display whose white is 100.1
  const double ld = skyig::shader::rec709Luminance(paleBlue);
  const glm::dvec3 shown = skyig::shader::compressToDisplay(paleBlue, ld, 100.1);
  EXPECT_LE(std::max(shown.r, std::max(shown.g, shown.b)), 100.1 + 1e-9);
  EXPECT_NEAR(skyig::shader::rec709Luminance(shown), ld, 1e-4);  // Rec.709 weights to 4 digits
  // Same hue: the channel differences from the luminance keep their ratios.
  EXPECT_NEAR((shown.b - ld) / (shown.r - ld), (paleBlue.b - ld) / (paleBlue.r - ld), 1e-9);
  EXPECT_GT(shown.b, shown.g);
  EXPECT_GT(shown.g, shown.r);
  // Brighter than white is white; a colour that fits is untouched.
  EXPECT_EQ(skyig::shader::compressToDisplay(paleBlue * 2.0, 2.0 * ld, 100.1), glm::dvec3(100.1));
  const glm::dvec3 dim = paleBlue * 0.5;
  EXPECT_EQ(skyig::shader::compressToDisplay(dim, 0.5 * ld, 100.1), dim);
}
