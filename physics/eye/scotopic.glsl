#ifndef SKYIG_TONE_SCOTOPIC_GLSL
#define SKYIG_TONE_SCOTOPIC_GLSL
// Scotopic and mesopic vision, Wang, Ji & Zhang 2011, eq. 20-21, after Jensen et al. 2000
// ("Night rendering", UUCS-00-016) and 2001, with V from XYZ as Larson et al. 1997 give it (the
// paper gives no formula for V): as luminance falls from 10^0.6 (about 4) to 0.01 cd/m^2 colour
// drains towards the rod-vision blue (x, y) = (0.25, 0.25) and the luminance becomes the
// scotopic luminance V.
#include "physics/common/constants.glsl"
#include "physics/common/color.glsl"

// Scotopic luminance from CIE XYZ (Larson, Rushmeier & Piatko 1997, eq. 2), same units as Y.
Float scotopicLuminance(IN(vec3) xyz) {
  if (xyz.x <= 0.0) return 0.0;
  return max(xyz.y * (1.33 * (1.0 + (xyz.y + xyz.z) / xyz.x) - 1.68), 0.0);
}

// Eq. 20: s = 1 photopic, 0 scotopic, a cubic blend in log10 Y between -2 and 0.6.
Float mesopicFactor(Float luminance) {
  Float t = clamp((logTen(max(luminance, 1e-12)) + 2.0) / 2.6, 0.0, 1.0);
  return 3.0 * t * t - 2.0 * t * t * t;
}

// Eq. 21: returns (x, y, Y) as the eye sees it. 0.4468 is Y/V of an equal-energy white.
vec3 mesopicxyY(IN(vec3) xyz) {
  vec3 xyY = xyzToxyY(xyz);
  Float s = mesopicFactor(xyz.y);
  Float v = scotopicLuminance(xyz);
  return vec3(mix(0.25, xyY.x, s), mix(0.25, xyY.y, s), mix(0.4468 * v, xyY.z, s));
}

#endif
