#ifndef SKYIG_TONE_DISPLAY_CURVE_GLSL
#define SKYIG_TONE_DISPLAY_CURVE_GLSL
// The channel's display mapping of a luminance, from the ToneBlock (common/uniforms.h): the
// scene's histogram-adjusted curve or Tumblin-Rushmeier, as adaptation.z selects. GPU only
// (it reads the block); the tone pass maps every pixel with it, and the displayed-star pass
// (passes/star_display.vert) the background each star sits on.
#include "tone/tone_reproduction.glsl"

DisplayModel toneDisplayModel() { return DisplayModel(display.x, display.y, display.z, display.w); }

float curvePoint(int i) { return curve[i >> 2][i & 3]; }

// The curve's display log10 luminance at a world luminance: linear between its 64 points,
// held at its ends (ToneCurve::displayLuminance on the CPU).
float curveAt(float worldLuminance) {
  float b = log(max(worldLuminance, 1e-30)) * 0.4342944819;
  float x = clamp((b - curveRange.x) / (curveRange.y - curveRange.x) * 63.0, 0.0, 63.0);
  int i = min(int(x), 62);
  return mix(curvePoint(i), curvePoint(i + 1), x - float(i));
}

// The display luminance (cd/m^2, before the display's white) for the eye's luminance (the
// mesopic Y of tone/scotopic.glsl). A program that maps every pixel (passes/tone.frag) is
// compiled for one operator, SKYIG_TONE_CURVE or SKYIG_TONE_TUMBLIN_RUSHMEIER, since llvmpipe
// would evaluate both sides of the uniform branch for each pixel; the per-star vertex stage
// keeps the branch.
float displayLuminanceFor(float eyeLuminance) {
#if defined(SKYIG_TONE_CURVE)
  return pow(10.0, curveAt(eyeLuminance));
#elif defined(SKYIG_TONE_TUMBLIN_RUSHMEIER)
  return tumblinRushmeierDisplayLuminance(eyeLuminance, adaptation.x, display.w);
#else
  if (adaptation.z > 0.5) return tumblinRushmeierDisplayLuminance(eyeLuminance, adaptation.x, display.w);
  return pow(10.0, curveAt(eyeLuminance));
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
