#ifndef SKYIG_EYE_TONE_CURVE_GLSL
#define SKYIG_EYE_TONE_CURVE_GLSL
// The histogram-adjusted tone curve (Ward Larson, Rushmeier & Piatko 1997, section 4) as a
// channel holds it: the display's log10 luminance at `points` points evenly spaced in the
// world's log10 luminance from log10Range.x to log10Range.y, linear between them and held at
// its ends. One source for both sides: the GPU reads the points from the tone block
// (render/passes/tone/display_curve.glsl), the CPU from ToneCurve (physics/eye/tone_curve.h).

// Where a world luminance (cd/m^2) falls on the curve: its continuous point index.
Float toneCurvePosition(Float worldLuminance, IN(vec2) log10Range, Float points) {
  Float b = log(max(worldLuminance, 1e-30)) * 0.4342944819;
  return clamp((b - log10Range.x) / (log10Range.y - log10Range.x) * (points - 1.0), 0.0, points - 1.0);
}

// The display luminance (cd/m^2) a fraction f of the way from a point of display log10 d0 to the
// next, of d1.
Float toneCurveLuminance(Float d0, Float d1, Float f) { return pow(10.0, mix(d0, d1, f)); }

#endif
