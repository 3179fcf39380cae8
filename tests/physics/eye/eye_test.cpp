// The pilot's eye: the threshold-versus-intensity function, the scene's tone curve and the
// adaptation in time.
#include "physics/eye/adaptation.h"
#include "physics/eye/tone_curve.h"
#include "physics/physics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace skyig::sky::eye;
namespace shader = skyig::shader;

// Ward Larson, Rushmeier & Piatko 1997 eq. 7: the five pieces meet (within 0.015 decade), the
// function rises with adaptation, and in daylight it is Weber's law with a 5.6% fraction.
TEST(Threshold, PiecesMeetAndDaylightFollowsWebersLaw) {
  for (double join : {-3.94, -1.44, -0.0184, 1.9})
    EXPECT_NEAR(shader::log10ThresholdLuminance(join - 1e-9), shader::log10ThresholdLuminance(join + 1e-9), 0.015) << join;
  double last = -10.0;
  for (double l = -6.0; l <= 6.0; l += 0.01) {
    EXPECT_GE(shader::log10ThresholdLuminance(l), last - 0.015);  // the fit steps down 0.012 at -1.44
    last = shader::log10ThresholdLuminance(l);
  }
  EXPECT_NEAR(shader::thresholdLuminance(1000.0) / 1000.0, std::pow(10.0, -1.255), 1e-9);
}

// A scene whose range fits the display keeps its contrasts up to its level (slope 1 in log
// luminance: a 2:1 ratio in the world is 2:1 on the display) and never exaggerates one above it;
// a scene wider than the display is compressed monotonically into it and no contrast is
// exaggerated (the linear ceiling).
TEST(ToneCurve, KeepsContrastsThatFitAndNeverExaggerates) {
  LuminanceHistogram narrow;
  for (double l = 0.01; l < 0.1; l *= 1.1) narrow.add(l, 0.1);
  const DisplayRange display{0.1, 100.0, 10.0};
  const ToneCurve a = histogramAdjustment(narrow, display);
  EXPECT_TRUE(a.linear);
  EXPECT_NEAR(a.displayLuminance(0.03) / a.displayLuminance(0.015), 2.0, 0.02);  // the level: 0.031
  for (double l = 0.03; l < 0.1; l *= 1.05) EXPECT_LE(a.displayLuminance(l * 1.05) / a.displayLuminance(l), 1.05 * 1.001) << l;

  LuminanceHistogram wide;
  for (double l = 1e-3; l < 1e5; l *= 1.2) wide.add(l, 0.05);
  wide.add(1.6e9, 6.8e-5);  // the sun
  const ToneCurve b = histogramAdjustment(wide, display);
  EXPECT_FALSE(b.linear);
  double previous = 0.0;
  for (double l = 1e-3; l < 1e5; l *= 1.05) {
    const double d = b.displayLuminance(l);
    EXPECT_GE(d, previous * (1.0 - 1e-6));
    EXPECT_GE(d, 0.1 * 0.999);
    EXPECT_LE(d, 100.0 * 1.001);
    // Display contrast over 5% of luminance is at most the world's (within the curve's sampling).
    EXPECT_LE(b.displayLuminance(l * 1.05) / d, 1.05 * 1.03);
    previous = d;
  }
  EXPECT_THROW(histogramAdjustment(LuminanceHistogram{}, display), std::invalid_argument);
  EXPECT_THROW(histogramAdjustment(narrow, DisplayRange{0.0, 100.0, 10.0}), std::invalid_argument);
}

// A bright day fits the display but its sky around the sun lies further above its level than the
// display's white lies above the level's matched luminance (a hazy afternoon: level 3,800 cd/m^2,
// the circumsolar sky to 110,000). The level is shown at its matched luminance (Tumblin &
// Rushmeier 1993), lowered only as far as the brightest tenth of the view needs to start under
// the top, where lowering the whole frame until the aureole fitted showed a bright day as dusk;
// contrasts are kept up to that knee and roll off above it: monotonic, the brightest extended
// part at the top (80% of white), never past it, no contrast exaggerated.
TEST(ToneCurve, ABrightDayKeepsItsLevelAndRollsItsBrightestTenthOffUnderTheTop) {
  LuminanceHistogram day;
  for (double l = 1300.0; l < 11000.0; l *= 1.05) day.add(l, 0.2);
  for (double l = 11000.0; l < 110000.0; l *= 1.05) day.add(l, 0.005);  // the sky near the sun
  const DisplayRange display{0.1, 100.0, 10.0};
  const ToneCurve c = histogramAdjustment(day, display);
  ASSERT_TRUE(c.linear);
  const double level = day.logMean(), knee = day.percentileLog10(1.0 - kKneeShare);
  const double top = std::log10(display.maxCdM2) - kHighlightHeadroomLog10;
  const double matched = std::log10(skyig::shader::tumblinRushmeierDisplayLuminance(level, level, display.adaptationCdM2));
  const double shown = std::min(matched, top - kShoulderHeadroomLog10 - (knee - std::log10(level)));
  EXPECT_NEAR(std::log10(c.displayLuminance(level)), shown, 0.01);
  // Lowered until the aureole fitted, the level would sit more than 3 times lower.
  const double fitted = top - (std::log10(110000.0) - std::log10(level));
  EXPECT_GT(std::log10(c.displayLuminance(level)), fitted + 0.5);
  EXPECT_NEAR(c.displayLuminance(level) / c.displayLuminance(level / 2.0), 2.0, 0.02);
  EXPECT_NEAR(c.displayLuminance(std::pow(10.0, knee) * 0.99) / c.displayLuminance(level), std::pow(10.0, knee) * 0.99 / level, 0.02);
  double previous = 0.0;
  for (double l = level; l < 100000.0; l *= 1.05) {
    const double d = c.displayLuminance(l);
    EXPECT_GT(d, previous) << l;
    EXPECT_LE(std::log10(d), top + 1e-3) << l;
    EXPECT_LE(c.displayLuminance(l * 1.05) / d, 1.05 * 1.001) << l;
    previous = d;
  }
  EXPECT_GT(c.displayLuminance(100000.0), 0.9 * std::pow(10.0, top));
  // The roll-off itself: slope 1 at the knee, the range's top at the headroom, identity where
  // the range fits.
  EXPECT_NEAR((shoulder(1e-4, 1.2, 0.4) - shoulder(0.0, 1.2, 0.4)) / 1e-4, 1.0, 1e-3);
  EXPECT_NEAR(shoulder(1.2, 1.2, 0.4), 0.4, 1e-12);
  EXPECT_EQ(shoulder(0.3, 0.35, 0.4), 0.3);
  EXPECT_EQ(shoulder(-0.5, 1.2, 0.4), -0.5);
  EXPECT_EQ(shoulder(0.3, -0.1, -0.3), 0.3);  // a knee above the scene's top: nothing rolls off
  // A scene of one bin and the sun's disc: its level can lie above its extended top; the curve
  // is still finite and rising.
  LuminanceHistogram flat;
  flat.add(5000.0, 4.0 * std::numbers::pi);
  flat.add(1.6e9, 6.8e-5);
  const ToneCurve f = histogramAdjustment(flat, display);
  EXPECT_TRUE(std::isfinite(f.displayLuminance(5000.0)));
  EXPECT_GT(f.displayLuminance(1.6e9), f.displayLuminance(5000.0));
}

// Pattanaik et al. 2000: light adaptation takes a fraction of a second, dark adaptation minutes
// (cones 110 s, rods 400 s); driven by the host's clock, two eyes fed the same times agree
// exactly; a step back in time (a restarted host) starts adapted.
TEST(EyeAdaptation, FollowsThePublishedTimeCourse) {
  EyeAdaptation eye;
  eye.reset(5000.0, 0.0);  // noon
  eye.step(1e-3, 0.0);     // the scene turns to night at t = 0
  eye.step(1e-3, 110.0);   // one cone pigment time constant later
  const double coneTravel = (std::log10(5000.0) - std::log10(eye.coneLevel())) / (std::log10(5000.0) + 3.0);
  EXPECT_NEAR(coneTravel, 1.0 - std::exp(-1.0), 1e-9);
  const double rodTravel = (std::log10(5000.0) - std::log10(eye.rodLevel())) / (std::log10(5000.0) + 3.0);
  EXPECT_NEAR(rodTravel, 1.0 - std::exp(-110.0 / 400.0), 1e-9);
  EXPECT_LT(eye.gain(1e-3), 0.05);  // still dazzled: the night looks darker than it will
  eye.step(1e-3, 3600.0);
  EXPECT_NEAR(eye.gain(1e-3), 1.0, 1e-3);  // adapted after an hour

  EyeAdaptation light;
  light.reset(1e-3, 0.0);
  light.step(5000.0, 0.0);
  light.step(5000.0, 1.0);  // a second: over six neural time constants of the rods
  EXPECT_NEAR(std::log10(light.level()), std::log10(5000.0), 0.01);

  EyeAdaptation a, b;
  for (int k = 0; k < 100; ++k) {
    const double t = k / 30.0, scene = k < 50 ? 3000.0 : 0.01;
    a.step(scene, t);
    b.step(scene, t);
  }
  EXPECT_EQ(a.level(), b.level());
  a.step(0.01, 0.5);  // the host restarted: its clock went back
  EXPECT_DOUBLE_EQ(a.level(), 0.01);
}
