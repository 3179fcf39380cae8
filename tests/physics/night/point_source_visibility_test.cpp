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

// On the default display (white 100.1, black 0.1 cd/m^2) a star drawn on the display's black,
// where the viewer's own threshold (Schaefer's at 0.1 cd/m^2) is the display's, has
// visibilities from 1 (just visible) to 3.1e3 while the eye's span 1 to 4.1e4 (Venus on the
// darkest sky). The display keeps the eye's visibilities up to the knee sqrt(3.1e3) = 55.5 and
// compresses above it with the slope s = log(55.5) / log(4.1e4 / 55.5) = 0.61; on a brighter
// displayed sky the range, and so the knee and the slope, are smaller; a display with the range
// keeps everything (slope 1).
TEST(PointSourceDisplay, CompressesTheWorldsVisibilityIntoTheDisplaysRange) {
  const double sigma = shader::kDisplayedPsfSigmaRad, psf = 2.0 * M_PI * sigma * sigma;
  auto range = [&](double displayed) {
    return shader::maxDisplayVisibility(displayed, 100.1, shader::pointSourceThresholdLux(displayed), psf);
  };
  EXPECT_NEAR(shader::maxWorldVisibility(), 4.07e4, 0.05e4);
  EXPECT_NEAR(range(0.1), 3.08e3, 0.05e3);
  const double k = shader::displayedVisibilityExponent(range(0.1));
  EXPECT_NEAR(k, 0.609, 0.005);
  EXPECT_NEAR(shader::displayedVisibilityKnee(k), std::sqrt(3.08e3), 1.0);
  EXPECT_EQ(shader::displayedVisibilityExponent(1e5), 1.0);
  // Below the threshold nothing; at it, the display's threshold; up to the knee V itself; above,
  // the compressed rank.
  const double sky = 2e-4, displaySky = 0.5;
  const double threshold = shader::pointSourceThresholdLux(sky), shownThreshold = shader::pointSourceThresholdLux(displaySky);
  EXPECT_EQ(shader::displayedIlluminance(0.99 * threshold, sky, shownThreshold, k), 0.0);
  EXPECT_NEAR(shader::displayedIlluminance(1.0001 * threshold, sky, shownThreshold, k), shownThreshold, 1e-3 * shownThreshold);
  EXPECT_NEAR(shader::displayedIlluminance(20.0 * threshold, sky, shownThreshold, k) / shownThreshold, 20.0, 1e-6);
  const double knee = shader::displayedVisibilityKnee(k);
  const double bright = shader::displayedIlluminance(1000.0 * threshold, sky, shownThreshold, k);
  EXPECT_NEAR(bright / shownThreshold, knee * std::pow(1000.0 / knee, k), 1e-6 * bright / shownThreshold);
  EXPECT_LT(bright / shownThreshold, 1000.0);
  // The brightest source on the darkest sky peaks at the display's white, whatever the displayed
  // sky around it: the slope falls as the displayed sky brightens (0.53 at 1.2 cd/m^2).
  for (double displayed : {0.1, 1.2, 10.0, 50.0}) {
    const double kHere = shader::displayedVisibilityExponent(range(displayed));
    EXPECT_LE(kHere, k);
    const double venus = shader::displayedIlluminance(shader::illuminanceOfMagnitude(-4.9), shader::kDarkestSkyCdM2,
                                                      shader::pointSourceThresholdLux(displayed), kHere);
    EXPECT_NEAR(displayed + venus / psf, 100.1, 0.5) << displayed;
  }
  EXPECT_NEAR(shader::displayedVisibilityExponent(range(1.2)), 0.529, 0.005);
}

// The display's threshold: a just-visible star's brightest pixel stands at least 4 codes over
// the displayed sky, with the star at a pixel's corner, at 1, 2 and 4 arcmin a pixel and on a
// displayed sky from near black to mid-grey (the default display, gamma 2.2); exactly 4 where
// the 8-bit frame, not the viewer's own threshold, is what limits.
TEST(PointSourceDisplay, AJustVisibleStarStandsFourCodesOverTheDisplayedSky) {
  const double amb = 0.1, max = 100.0, gamma = 2.2;
  for (double arcmin : {1.0, 2.0, 4.0})
    for (int code : {3, 31, 80, 160}) {
      const double pixelSr = std::pow(arcmin / 60.0 * M_PI / 180.0, 2.0);
      const double sigmaPx = std::max(shader::kDisplayedPsfSigmaRad / std::sqrt(pixelSr), shader::kDisplayedPsfMinSigmaPx);
      const double background = amb + max * std::pow(code / 255.0, gamma);
      const double step = shader::displayThresholdStep(background, amb, max, gamma);
      EXPECT_NEAR(amb + max * std::pow((code + 4) / 255.0, gamma) - background, step, 1e-9 * background);
      const double peakSr = shader::starPsfPeakSolidAngle(pixelSr, sigmaPx);
      const double lux = shader::displayedThresholdLux(background, step, peakSr);
      const double brightest = background + lux * shader::starPsfCornerPeakWeight(sigmaPx) / pixelSr;
      const double codes = 255.0 * (shader::displayValue(brightest, amb, max, gamma) - code / 255.0);
      const bool viewerLimits = shader::pointSourceThresholdLux(background) > step * peakSr;
      std::printf("  %.0f' a pixel, code %d: %.2f codes (%s)\n", arcmin, code, codes, viewerLimits ? "the viewer's" : "the frame's");
      EXPECT_GE(codes, 4.0 - 1e-6);
      if (!viewerLimits) {
        EXPECT_NEAR(codes, 4.0, 1e-6);
      }
    }
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

// The PSF integrated over each pixel keeps the star's light at any width, wherever the star sits
// in its pixel (a Gaussian sampled at the pixel centres loses or gains it below 0.7 px), and the
// corner's brightest pixel is the closed form (erf(1 / (sigma sqrt 2)) / 2)^2.
TEST(StarPsf, IntegratedOverPixelsItKeepsTheLightAtAnyWidth) {
  for (double x : {-2.3, -0.5, 0.0, 0.2, 1.7}) EXPECT_NEAR(shader::starErf(x), std::erf(x), 2e-7) << x;
  for (double sigma : {0.1, 0.3, 0.5, 1.0, 2.0})
    for (const glm::dvec2 phase : {glm::dvec2(0.0), glm::dvec2(0.5), glm::dvec2(0.25, -0.4)}) {
      double sum = 0.0, peak = 0.0;
      for (int y = -12; y <= 12; ++y)
        for (int x = -12; x <= 12; ++x) {
          const double w = shader::starPsfPixelWeight(glm::dvec2(x, y) - phase, sigma);
          sum += w;
          peak = std::max(peak, w);
        }
      EXPECT_NEAR(sum, 1.0, 1e-3) << sigma;
      if (phase == glm::dvec2(0.5)) {
        EXPECT_NEAR(peak, shader::starPsfCornerPeakWeight(sigma), 1e-6);
        EXPECT_NEAR(peak, std::pow(std::erf(1.0 / (sigma * std::sqrt(2.0))) / 2.0, 2.0), 1e-6);
      }
    }
  EXPECT_NEAR(shader::starPsfCornerPeakWeight(0.01), 0.25, 1e-6);
  EXPECT_NEAR(shader::starPsfCornerPeakWeight(3.0), std::exp(-0.25 / 9.0) / (2.0 * M_PI * 9.0), 2e-4);  // less the box, 1%
}
