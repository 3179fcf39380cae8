#ifndef SKYIG_TONE_TUMBLIN_RUSHMEIER_GLSL
#define SKYIG_TONE_TUMBLIN_RUSHMEIER_GLSL
// Tumblin & Rushmeier 1993, "Tone reproduction for realistic images", IEEE CG&A 13(6):
// match the brightness (Stevens & Stevens 1963) the eye perceives in the world and on the
// display; Wang, Ji & Zhang 2011, eq. 13-19.
//
// The original works in lamberts: B = 10^beta(La) L^alpha(La) with
//   alpha(La) = 0.4 log10 La + 2.92,  beta(La) = -0.4 (log10 La)^2 - 2.584 log10 La + 2.0208.
// Wang, Ji & Zhang's eq. 14 (alpha = 0.4 log10 La + 1.519, beta = -0.4 (log10 La)^2 + 0.218
// log10 La + 6.1642; printed with L_w where the adaptation luminance La belongs) is the same
// pair rewritten for La in cd/m^2 (substitute La -> pi 1e-4 La); the test suite checks that
// identity. We keep the original constants and convert units here.
#include "physics/common/constants.glsl"

const Float LAMBERTS_PER_CD_M2 = PI * 1e-4;

// Stevens' data reach down to about 1e-3 cd/m^2; below that alpha tends to zero and the
// mapping would invert, so adaptation levels are held at or above this floor.
const Float TR_MIN_ADAPTATION_CD_M2 = 1e-3;

Float trAlpha(Float adaptationCdM2) {
  return 0.4 * logTen(max(adaptationCdM2, TR_MIN_ADAPTATION_CD_M2) * LAMBERTS_PER_CD_M2) + 2.92;
}

Float trBeta(Float adaptationCdM2) {
  Float l = logTen(max(adaptationCdM2, TR_MIN_ADAPTATION_CD_M2) * LAMBERTS_PER_CD_M2);
  return -0.4 * l * l - 2.584 * l + 2.0208;
}

// Eq. 16: the display luminance (cd/m^2) whose brightness, seen adapted to displayAdaptation,
// equals that of worldLuminance seen adapted to worldAdaptation.
Float tumblinRushmeierDisplayLuminance(Float worldLuminance, Float worldAdaptation,
                                       Float displayAdaptation) {
  Float alphaW = trAlpha(worldAdaptation);
  Float alphaD = trAlpha(displayAdaptation);
  Float betaW = trBeta(worldAdaptation);
  Float betaD = trBeta(displayAdaptation);
  Float lw = max(worldLuminance, 0.0) * LAMBERTS_PER_CD_M2;
  return pow(10.0, (betaW - betaD) / alphaD) * pow(lw, alphaW / alphaD) / LAMBERTS_PER_CD_M2;
}

// Eq. 17-18: the frame-buffer value n in [0, 1] that makes a display of maximum luminance
// maxLuminance, ambient (black-level) luminance ambient and gamma show displayLuminance.
Float displayValue(Float displayLuminance, Float ambient, Float maxLuminance, Float gamma) {
  return pow(clamp((displayLuminance - ambient) / maxLuminance, 0.0, 1.0), 1.0 / gamma);
}

#endif
