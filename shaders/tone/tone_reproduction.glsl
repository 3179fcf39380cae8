#ifndef SKYIG_TONE_TONE_REPRODUCTION_GLSL
#define SKYIG_TONE_TONE_REPRODUCTION_GLSL
// The whole tone reproduction of a pixel (Wang, Ji & Zhang 2011, section 3): mesopic vision
// (eq. 20-21), Tumblin-Rushmeier brightness matching of the luminance (eq. 16), the display
// model (eq. 17-18) per Rec.709 channel. The chromaticity is kept; only the luminance is mapped.
#include "tone/tumblin_rushmeier.glsl"
#include "tone/scotopic.glsl"

struct DisplayModel {
  Float maxLuminance;         // L_dmax, cd/m^2
  Float ambientLuminance;     // L_amb, cd/m^2 (black level plus room light on the screen)
  Float gamma;                // display gamma
  Float adaptationLuminance;  // L_a(d): the viewer's adaptation to the display, cd/m^2
};

// Display luminance (linear Rec.709, cd/m^2) for a world colour (linear Rec.709, cd/m^2)
// seen with the eye adapted to worldAdaptation (cd/m^2).
vec3 toneReproduceLinear(IN(vec3) worldRgb, Float worldAdaptation, IN(DisplayModel) display) {
  vec3 xyY = mesopicxyY(rec709ToXyz(max(worldRgb, vec3(0.0))));
  Float ld = tumblinRushmeierDisplayLuminance(xyY.z, worldAdaptation, display.adaptationLuminance);
  return max(xyzToRec709(xyYToXyz(vec3(xyY.x, xyY.y, ld))), vec3(0.0));
}

// Frame-buffer values n in [0, 1] (eq. 18) for a world colour.
vec3 toneReproduce(IN(vec3) worldRgb, Float worldAdaptation, IN(DisplayModel) display) {
  vec3 ld = toneReproduceLinear(worldRgb, worldAdaptation, display);
  return vec3(displayValue(ld.x, display.ambientLuminance, display.maxLuminance, display.gamma),
              displayValue(ld.y, display.ambientLuminance, display.maxLuminance, display.gamma),
              displayValue(ld.z, display.ambientLuminance, display.maxLuminance, display.gamma));
}

#endif
