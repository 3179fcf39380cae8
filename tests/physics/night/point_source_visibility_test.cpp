// The point-source threshold and the display mapping of stars (physics/eye/
// point_source_visibility.glsl, the code the displayed-star pass runs, compiled as C++):
// Schaefer's (1990) threshold gives the naked-eye limiting magnitudes observers report, and the
// display keeps a star's visibility (docs/night-sky-stars.md, "On the display").
#include "physics/stars/star_physics.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace skyig;

namespace {

// Sky brightness in V mag/arcsec^2 to cd/m^2, Schaefer's conversion B(nL) = 34.08 exp(20.7233 -
// 0.92104 mu) (Schaefer 1990; 1 nL = 1e-5 / pi cd/m^2).
double skyCdM2(double magPerArcsec2) { return 34.08 * std::exp(20.7233 - 0.92104 * magPerArcsec2) * 1e-5 / M_PI; }

}  // namespace

// A dark site (21.8 mag/arcsec^2, 2.1e-4 cd/m^2) shows stars to magnitude 6.5, the classical
// naked-eye limit; a suburban sky of 19 mag/arcsec^2 to 4.8 (Bortle class 7, 4.6-5.0); by day,
// on a blue sky of 5000 cd/m^2, only a source brighter than about -4 is seen: Venus at its
// brightest (-4.6), as observers do see it by day.
TEST(PointSourceThreshold, ReproducesTheNakedEyeLimitingMagnitudes) {
  EXPECT_NEAR(skyCdM2(21.8), 2.07e-4, 0.02e-4);
  EXPECT_NEAR(shader::limitingMagnitude(skyCdM2(21.8)), 6.5, 0.1);
  EXPECT_NEAR(shader::limitingMagnitude(skyCdM2(22.0)), 6.6, 0.1);
  const double suburban = shader::limitingMagnitude(skyCdM2(19.0));
  EXPECT_GT(suburban, 4.6);
  EXPECT_LT(suburban, 5.0);
  const double day = shader::limitingMagnitude(5000.0);
  EXPECT_LT(day, -3.5);
  EXPECT_GT(day, -4.6);
  // On a black background, the rods' absolute threshold: 1.7e-9 lux, magnitude 8.
  EXPECT_NEAR(shader::pointSourceThresholdLux(0.0), 1.706e-9, 0.001e-9);
  // A magnitude-0 star gives 2.54e-6 lux (the V zero point, e.g. Allen's Astrophysical Quantities).
  EXPECT_NEAR(shader::illuminanceOfMagnitude(0.0), 2.54e-6, 0.03e-6);
}

// The threshold rises steadily with the background, and the rods hand over to the cones near
// Schaefer's 1500 nL (4.8e-3 cd/m^2) without a jump: the smaller of the two branches.
TEST(PointSourceThreshold, RisesWithTheBackgroundWithoutAJump) {
  double previous = 0.0;
  for (double logB = -6.0; logB <= 5.0; logB += 0.01) {
    const double t = shader::pointSourceThresholdLux(std::pow(10.0, logB));
    EXPECT_GT(t, previous) << logB;
    if (previous > 0.0) {
      EXPECT_LT(t / previous, 1.03) << logB;
    }
    previous = t;
  }
  const double crossing = 1620.0 * 1e-5 / M_PI;  // 1620 nL
  EXPECT_NEAR(shader::rodThresholdLux(crossing) / shader::coneThresholdLux(crossing), 1.0, 0.02);
}

// On the default display (white 100.1, black 0.1 cd/m^2) a star drawn on the display's black
// has visibilities from 1 (just visible) to 3.1e3 while the eye's span 1 to 4.1e4 (Venus on the
// darkest sky). The display keeps the eye's visibilities up to the knee sqrt(3.1e3) = 55.5 and
// compresses above it with the slope s = log(55.5) / log(4.1e4 / 55.5) = 0.61; on a brighter
// displayed sky the range, and so the knee and the slope, are smaller; a display with the range
// keeps everything (slope 1).
TEST(PointSourceDisplay, CompressesTheWorldsVisibilityIntoTheDisplaysRange) {
  EXPECT_NEAR(shader::maxWorldVisibility(), 4.07e4, 0.05e4);
  EXPECT_NEAR(shader::maxDisplayVisibility(0.1, 100.1), 3.08e3, 0.05e3);
  const double k = shader::displayedVisibilityExponent(0.1, 100.1);
  EXPECT_NEAR(k, 0.609, 0.005);
  EXPECT_NEAR(shader::displayedVisibilityKnee(k), std::sqrt(3.08e3), 1.0);
  EXPECT_EQ(shader::displayedVisibilityExponent(0.001, 1e5), 1.0);
  // Below the threshold nothing; at it, the display's threshold; up to the knee V itself; above,
  // the compressed rank.
  const double sky = 2e-4, displaySky = 0.5;
  const double threshold = shader::pointSourceThresholdLux(sky), shownThreshold = shader::pointSourceThresholdLux(displaySky);
  EXPECT_EQ(shader::displayedIlluminance(0.99 * threshold, sky, displaySky, k), 0.0);
  EXPECT_NEAR(shader::displayedIlluminance(1.0001 * threshold, sky, displaySky, k), shownThreshold, 1e-3 * shownThreshold);
  EXPECT_NEAR(shader::displayedIlluminance(20.0 * threshold, sky, displaySky, k) / shownThreshold, 20.0, 1e-6);
  const double knee = shader::displayedVisibilityKnee(k);
  const double bright = shader::displayedIlluminance(1000.0 * threshold, sky, displaySky, k);
  EXPECT_NEAR(bright / shownThreshold, knee * std::pow(1000.0 / knee, k), 1e-6 * bright / shownThreshold);
  EXPECT_LT(bright / shownThreshold, 1000.0);
  // The brightest source on the darkest sky peaks at the display's white, whatever the displayed
  // sky around it: the slope falls as the displayed sky brightens (0.53 at 1.2 cd/m^2).
  const double sigma = shader::kDisplayedPsfSigmaRad;
  for (double displayed : {0.1, 1.2, 10.0, 50.0}) {
    const double kHere = shader::displayedVisibilityExponent(displayed, 100.1);
    EXPECT_LE(kHere, k);
    const double venus =
        shader::displayedIlluminance(shader::illuminanceOfMagnitude(-4.9), shader::kDarkestSkyCdM2, displayed, kHere);
    EXPECT_NEAR(displayed + venus / (2.0 * M_PI * sigma * sigma), 100.1, 0.5) << displayed;
  }
  EXPECT_NEAR(shader::displayedVisibilityExponent(1.2, 100.1), 0.529, 0.005);
}

// Colour: a star the cones see ten times over keeps its chromaticity; one only the rods see is
// drawn in the rods' white (x, y) = (0.25, 0.25), with the displayed luminance either way.
TEST(PointSourceDisplay, ColourOnlyWhereTheConesSeeIt) {
  const glm::dvec3 red(3e-6, 1e-6, 0.3e-6);  // lux per channel, a reddish star
  const double y = shader::rec709Luminance(red);
  const glm::dvec3 shown = shader::displayedPointSourceRec709(red, 1e-6, 1e-3);
  EXPECT_NEAR(shader::rec709Luminance(shown), 1e-3, 1e-9);
  ASSERT_GT(y / shader::coneThresholdLux(1e-6), 10.0);
  const glm::dvec3 a = shader::xyzToxyY(shader::rec709ToXyz(shown)), b = shader::xyzToxyY(shader::rec709ToXyz(red));
  EXPECT_NEAR(a.x, b.x, 1e-6);  // the Rec.709 matrices are inverse to 7 digits
  EXPECT_NEAR(a.y, b.y, 1e-6);
  const glm::dvec3 faint = red * (0.9 * shader::coneThresholdLux(1e-3) / y);
  const glm::dvec3 grey = shader::xyzToxyY(shader::rec709ToXyz(shader::displayedPointSourceRec709(faint, 1e-3, 1e-3)));
  EXPECT_NEAR(grey.x, 0.25, 1e-6);
  EXPECT_NEAR(grey.y, 0.25, 1e-6);
}
