#ifndef SKYIG_NIGHT_POINT_SOURCE_VISIBILITY_GLSL
#define SKYIG_NIGHT_POINT_SOURCE_VISIBILITY_GLSL
// Point sources (stars, planets) as the eye sees them, for the display: written once for the
// displayed-star pass (render/passes/night/star_display.vert) and the CPU tests (physics/stars/star_physics.h).
// docs/night-sky-stars.md, "On the display", derives what follows.
//
// A star is far below the eye's critical area (Ricco's law: below about 10 arcmin the eye
// integrates luminance x area), so whether it is seen depends on its illuminance E at the eye
// and on the luminance B of the background it sits on, never on its shape. The threshold is
// Hecht's form as Schaefer fitted it to Knoll, Tousey & Hulburt's (1946) and Blackwell's (1946)
// point-source data (Schaefer 1990, "Telescopic limiting magnitudes", PASP 102, 212, eq. 2):
//   I_th = c1 (1 + sqrt(c2 B))^2,  I in foot-candles, B in nanolamberts,
//   night (rods):  c1 = 10^-9.8,  c2 = 10^-1.9   (Schaefer uses it below B = 1500 nL),
//   day (cones):   c1 = 10^-8.35, c2 = 10^-5.9,
// and a star of V magnitude m gives I = 10^(-0.4 (m + 16.57)) foot-candles. In SI (1 fc =
// 10.7639 lux, 1 nL = 1e-5 / pi cd/m^2 = 3.18310e-6 cd/m^2):
//   E_th = a (1 + sqrt(b B))^2,  B in cd/m^2, E in lux,
//   night: a = 10^-9.8 x 10.7639 = 1.70599e-9 lux,  b = 10^-1.9 / 3.18310e-6 = 3955.1 m^2/cd,
//   day:   a = 10^-8.35 x 10.7639 = 4.80812e-8 lux, b = 10^-5.9 / 3.18310e-6 = 0.395516 m^2/cd.
// The eye sees with whichever system is more sensitive, so the threshold is the smaller of the
// two: that is Schaefer's night branch up to 1620 nL (5.2e-3 cd/m^2), where the branches cross
// (at his 1500 nL they differ by 8%), and continuous. At a dark sky of 21.8 mag/arcsec^2
// (2.07e-4 cd/m^2) the faintest star seen is m = 6.53; at 19 mag/arcsec^2 (2.7e-3 cd/m^2), 4.77.
#include "physics/common/constants.glsl"
#include "physics/common/color.glsl"
#include "physics/eye/tumblin_rushmeier.glsl"

const Float kLuxPerFootCandle = 10.7639104;
const Float kThresholdNightLux = 1.70599e-9;
const Float kThresholdNightPerCdM2 = 3955.1;
const Float kThresholdDayLux = 4.80812e-8;
const Float kThresholdDayPerCdM2 = 0.395516;

// The rods' (night) and the cones' (day) threshold illuminance, lux, for a point source on a
// background of `backgroundCdM2`.
Float rodThresholdLux(Float backgroundCdM2) {
  Float s = 1.0 + sqrt(kThresholdNightPerCdM2 * max(backgroundCdM2, 0.0));
  return kThresholdNightLux * s * s;
}
Float coneThresholdLux(Float backgroundCdM2) {
  Float s = 1.0 + sqrt(kThresholdDayPerCdM2 * max(backgroundCdM2, 0.0));
  return kThresholdDayLux * s * s;
}
Float pointSourceThresholdLux(Float backgroundCdM2) {
  return min(rodThresholdLux(backgroundCdM2), coneThresholdLux(backgroundCdM2));
}

// Illuminance (lux) of a star of V magnitude m, and back (Schaefer 1990, eq. 1).
Float illuminanceOfMagnitude(Float m) { return kLuxPerFootCandle * pow(10.0, -0.4 * (m + 16.57)); }
Float magnitudeOfIlluminance(Float lux) { return -16.57 - 2.5 * logTen(lux / kLuxPerFootCandle); }

// The naked-eye limiting magnitude on a background of `backgroundCdM2`.
Float limitingMagnitude(Float backgroundCdM2) {
  return magnitudeOfIlluminance(pointSourceThresholdLux(backgroundCdM2));
}

// The displayed star's point-spread function, an angle: a Gaussian of this standard deviation
// (2 arcmin), 4.7 arcmin at half maximum, well inside the critical area of the viewer of the
// display, so the viewer integrates it as the eye integrates a star; integrated over each pixel
// (star_psf.glsl, starPsfPixelWeight), so a PSF narrower than a pixel keeps its light. The floor
// only keeps the width above zero.
const Float kDisplayedPsfSigmaRad = 2.0 / 60.0 * DEG;
const Float kDisplayedPsfMinSigmaPx = 0.1;

// The brightest point source the eye meets: Venus at its greatest brilliance (V = -4.9) on the
// darkest natural sky (22 mag/arcsec^2, 1.7e-4 cd/m^2). Its visibility E / E_th is the largest
// that the display must rank: 4.1e4.
const Float kBrightestSourceMagnitude = -4.9;
const Float kDarkestSkyCdM2 = 1.72e-4;

Float maxWorldVisibility() {
  return illuminanceOfMagnitude(kBrightestSourceMagnitude) / pointSourceThresholdLux(kDarkestSkyCdM2);
}

// The display's threshold for a point (docs/night-sky-stars.md, "The display's threshold").
// Schaefer's threshold at the display's own luminance is what the viewer needs for a point on a
// perfect display, and on a fine channel that is a code or two of an 8-bit frame. But the frame
// is quantised and dithered (+-1 LSB, render/glsl/dither.glsl): a neighbour of the star can sit a
// code up and the star's pixel a code down, and a point the viewer must find among thousands of
// dithered pixels needs a contrast several times that noise (Rose 1948: about 5 times its rms,
// 0.41 LSB for a triangular +-1 LSB dither). The display threshold is therefore the larger of
// the two: Schaefer's at the display's luminance, and the star's brightest pixel
// kDisplayThresholdCodes codes over the displayed sky around it, with the star at the worst
// place, a pixel's corner (physics/stars/star_psf.glsl, starPsfPeakSolidAngle). Both are fixed
// by the display and its pixel scale, so a star the eye just sees looks the same on a channel
// of 1, 2 or 4 arcmin a pixel.
const Float kDisplayThresholdCodes = 4.0;

// The display luminance step (cd/m^2) that raises a pixel shown at `backgroundCdM2` by
// kDisplayThresholdCodes codes, through the display model's eq. 18 (physics/eye/
// tumblin_rushmeier.glsl, displayValue) and its inverse, L = L_amb + L_max n^gamma.
Float displayThresholdStep(Float backgroundCdM2, Float ambientCdM2, Float maxCdM2, Float gamma) {
  Float n = displayValue(backgroundCdM2, ambientCdM2, maxCdM2, gamma);
  Float up = min(n + kDisplayThresholdCodes / 255.0, 1.0);
  return max(ambientCdM2 + maxCdM2 * pow(up, gamma) - max(backgroundCdM2, ambientCdM2), 0.0);
}

// The displayed illuminance (lux) of a just-visible star: the larger of the viewer's own point
// threshold at the displayed sky (Schaefer) and the display threshold, a brightest pixel
// `stepCdM2` over it.
Float displayedThresholdLux(Float displayBackgroundCdM2, Float stepCdM2, Float peakSolidAngle) {
  return max(pointSourceThresholdLux(displayBackgroundCdM2), stepCdM2 * peakSolidAngle);
}

// The largest displayed visibility (in units of displayedThresholdLux) a display of white
// `whiteCdM2` has for a star drawn on its luminance `backgroundCdM2` there: its brightest pixel
// reaches white.
Float maxDisplayVisibility(Float backgroundCdM2, Float whiteCdM2, Float thresholdLux, Float peakSolidAngle) {
  return max((whiteCdM2 - backgroundCdM2) * peakSolidAngle / thresholdLux, 1.0);
}

// Displayed visibility V_d for a world visibility V (WLRP97's ceiling idea for points: compress,
// never exaggerate, and only where the display lacks the range). Up to a knee V_k the display
// keeps V as it is (a just-visible star is at the display's threshold, a star 20x its threshold
// is 20x the display's); above it, log V_d = log V_k + s (log V - log V_k), so that the brightest
// source the eye meets (maxWorldVisibility) peaks at the display's white. The knee is the
// geometric middle of the display's range, V_k = sqrt(V_d,max): the faint half of the display's
// range is the eye's own, the bright half holds the rest in rank. (A single power V^k over the
// whole range compressed the faint stars too and left a moonless sky's stars a code or two above
// it.) The slope s for a display's range `displayRange` (maxDisplayVisibility); 1 where the
// display has the eye's range. Stars on the same displayed sky share it, so they rank by
// magnitude.
Float displayedVisibilityExponent(Float displayRange) {
  Float range = log(max(displayRange, 1.0)), eye = log(maxWorldVisibility());
  if (range >= eye) return 1.0;
  return 0.5 * range / (eye - 0.5 * range);
}

// The knee V_k that goes with a slope s: from s = (L/2) / (L_eye - L/2), L = log V_d,max,
// log V_k = L/2 = s L_eye / (1 + s).
Float displayedVisibilityKnee(Float exponent) {
  return exp(exponent * log(maxWorldVisibility()) / (1.0 + exponent));
}

Float displayedVisibility(Float visibility, Float exponent) {
  Float knee = displayedVisibilityKnee(exponent);
  return visibility <= knee ? visibility : knee * pow(visibility / knee, exponent);
}

// The illuminance (lux, at the viewer of the display) that a point source of illuminance
// `worldLux` on a background of `worldBackgroundCdM2` gets on a display whose threshold there is
// `displayedThreshold` (displayedThresholdLux): V_d = displayedVisibility(V) times it, and
// nothing below the eye's threshold (V < 1).
Float displayedIlluminance(Float worldLux, Float worldBackgroundCdM2, Float displayedThreshold, Float exponent) {
  Float v = worldLux / pointSourceThresholdLux(worldBackgroundCdM2);
  if (!(v > 1.0)) return 0.0;
  return displayedVisibility(v, exponent) * displayedThreshold;
}

// How much of its colour the eye sees in a point source: 0 where only the rods detect it (the
// cones' visibility E / E_th,cones <= 1), 1 ten times above the cones' threshold, a cubic
// between in log10 (as the mesopic blend of physics/eye/scotopic.glsl).
Float pointSourceColourFactor(Float worldLux, Float worldBackgroundCdM2) {
  Float t = clamp(logTen(max(worldLux / coneThresholdLux(worldBackgroundCdM2), 1e-30)), 0.0, 1.0);
  return 3.0 * t * t - 2.0 * t * t * t;
}

// The displayed source's linear Rec.709 illuminance: luminance `displayedLux`, chromaticity the
// source's where the cones see it, drained towards the rods' white (x, y) = (0.25, 0.25) of
// physics/eye/scotopic.glsl where they do not. Gamut excursions are left to the tone pass, which
// compresses the sum along its hue.
vec3 displayedPointSourceRec709(IN(vec3) worldRec709Lux, Float worldBackgroundCdM2, Float displayedLux) {
  vec3 xyY = xyzToxyY(rec709ToXyz(max(worldRec709Lux, vec3(0.0))));
  Float s = pointSourceColourFactor(xyY.z, worldBackgroundCdM2);
  return xyzToRec709(xyYToXyz(vec3(mix(0.25, xyY.x, s), mix(0.25, xyY.y, s), displayedLux)));
}

#endif
