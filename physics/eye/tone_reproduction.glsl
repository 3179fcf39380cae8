#ifndef SKYIG_TONE_TONE_REPRODUCTION_GLSL
#define SKYIG_TONE_TONE_REPRODUCTION_GLSL
// The whole tone reproduction of a pixel (Wang, Ji & Zhang 2011, section 3): mesopic vision
// (eq. 20-21), Tumblin-Rushmeier brightness matching of the luminance (eq. 16), the display
// model (eq. 17-18) per Rec.709 channel. The chromaticity is kept; only the luminance is mapped.
#include "physics/eye/tumblin_rushmeier.glsl"
#include "physics/eye/scotopic.glsl"

struct DisplayModel {
  Float maxLuminance;         // L_dmax, cd/m^2
  Float ambientLuminance;     // L_amb, cd/m^2 (black level plus room light on the screen)
  Float gamma;                // display gamma
  Float viewerAdaptationLuminance;  // L_a(d): the viewer's adaptation to the display, cd/m^2
};

// A display colour of luminance `ld` (cd/m^2) that the display can show, whose white is
// `white` (cd/m^2): a colour brighter in one channel than the display is desaturated towards
// white along its own hue (keeping its luminance), never clipped channel by channel (which
// turned a bright pale-blue horizon cyan); a luminance above white is white. Negative channels
// (outside the Rec.709 gamut) are desaturated the same way.
vec3 compressToDisplay(IN(vec3) rgb, Float ld, Float white) {
  if (ld >= white) return vec3(white);
  Float hi = max(rgb.x, max(rgb.y, rgb.z));
  Float lo = min(rgb.x, min(rgb.y, rgb.z));
  Float s = 1.0;
  if (hi > white) s = min(s, (white - ld) / (hi - ld));
  if (lo < 0.0) s = min(s, ld / max(ld - lo, 1e-30));
  return vec3(ld) + max(s, 0.0) * (rgb - vec3(ld));
}

// Display luminance (linear Rec.709, cd/m^2) for a world colour (linear Rec.709, cd/m^2)
// seen with the eye adapted to worldAdaptation (cd/m^2).
vec3 toneReproduceLinear(IN(vec3) worldRgb, Float worldAdaptation, IN(DisplayModel) display) {
  vec3 xyY = mesopicxyY(rec709ToXyz(max(worldRgb, vec3(0.0))));
  Float ld = tumblinRushmeierDisplayLuminance(xyY.z, worldAdaptation, display.viewerAdaptationLuminance);
  return compressToDisplay(xyzToRec709(xyYToXyz(vec3(xyY.x, xyY.y, ld))), ld,
                           display.ambientLuminance + display.maxLuminance);
}

// The same through a display curve: `displayLog10` is the display log10 luminance the scene's
// tone curve gives the eye's luminance (physics/eye/tone_curve.h), looked up by the caller.
vec3 toneReproduceLinearWithCurve(IN(vec3) xyY, Float displayLog10, IN(DisplayModel) display) {
  Float ld = pow(10.0, displayLog10);
  return compressToDisplay(xyzToRec709(xyYToXyz(vec3(xyY.x, xyY.y, ld))), ld,
                           display.ambientLuminance + display.maxLuminance);
}

// Frame-buffer values n in [0, 1] (eq. 18) for a display colour.
vec3 displayValues(IN(vec3) ld, IN(DisplayModel) display) {
  return vec3(displayValue(ld.x, display.ambientLuminance, display.maxLuminance, display.gamma),
              displayValue(ld.y, display.ambientLuminance, display.maxLuminance, display.gamma),
              displayValue(ld.z, display.ambientLuminance, display.maxLuminance, display.gamma));
}

// Frame-buffer values n in [0, 1] (eq. 18) for a world colour.
vec3 toneReproduce(IN(vec3) worldRgb, Float worldAdaptation, IN(DisplayModel) display) {
  return displayValues(toneReproduceLinear(worldRgb, worldAdaptation, display), display);
}

#endif
