#ifndef SKYIG_TONE_DISPLAY_CURVE_GLSL
#define SKYIG_TONE_DISPLAY_CURVE_GLSL
// The channel's display mapping of a luminance, from the ToneBlock (render/glsl/uniforms.h): the
// scene's histogram-adjusted curve or Tumblin-Rushmeier, as adaptation.z selects. GPU only
// (it reads the block); the tone pass maps every pixel with it, and the displayed-star pass
// (render/passes/night/star_display.vert) the background each star sits on.
#include "physics/eye/tone_reproduction.glsl"
#include "physics/eye/tone_curve.glsl"

DisplayModel toneDisplayModel() { return DisplayModel(display.x, display.y, display.z, display.w); }

float curvePoint(int i) { return curve[i >> 2][i & 3]; }

// The curve's display luminance at a world luminance, from its 64 points in the block
// (physics/eye/tone_curve.glsl; ToneCurve::displayLuminance on the CPU).
float curveLuminanceAt(float worldLuminance) {
  float x = toneCurvePosition(worldLuminance, curveRange.xy, 64.0);
  int i = min(int(x), 62);
  return toneCurveLuminance(curvePoint(i), curvePoint(i + 1), x - float(i));
}

// The display luminance (cd/m^2, before the display's white) for the eye's luminance (the
// mesopic Y of physics/eye/scotopic.glsl). A program that maps every pixel (render/passes/tone/tone.frag) is
// compiled for one operator, SKYIG_TONE_CURVE or SKYIG_TONE_TUMBLIN_RUSHMEIER, since llvmpipe
// would evaluate both sides of the uniform branch for each pixel; the per-star vertex stage
// keeps the branch.
float displayLuminanceFor(float eyeLuminance) {
#if defined(SKYIG_TONE_CURVE)
  return curveLuminanceAt(eyeLuminance);
#elif defined(SKYIG_TONE_TUMBLIN_RUSHMEIER)
  return tumblinRushmeierDisplayLuminance(eyeLuminance, adaptation.x, display.w);
#else
  if (adaptation.z > 0.5) return tumblinRushmeierDisplayLuminance(eyeLuminance, adaptation.x, display.w);
  return curveLuminanceAt(eyeLuminance);
#endif
}

// The display colour (linear Rec.709, cd/m^2) of a world colour (linear Rec.709, cd/m^2).
// SKYIG_PHOTOPIC: every pixel is known to be bright enough for cone vision (sky/shown_layers.h),
// where eq. 21 keeps the chromaticity and the luminance (mesopicFactor 1), so the colour is
// scaled by ld / Y: the same value without the xyY round trip.
vec3 toneMapLinear(vec3 world) {
#ifdef SKYIG_PHOTOPIC
  vec3 w = max(world, vec3(0.0));
  float y = rec709Luminance(w);
  float ld = displayLuminanceFor(y);
  return compressToDisplay(w * (ld / max(y, 1e-30)), ld, display.y + display.x);
#else
  vec3 xyY = mesopicxyY(rec709ToXyz(max(world, vec3(0.0))));
  float ld = displayLuminanceFor(xyY.z);
  return compressToDisplay(xyzToRec709(xyYToXyz(vec3(xyY.x, xyY.y, ld))), ld, display.y + display.x);
#endif
}

#endif
