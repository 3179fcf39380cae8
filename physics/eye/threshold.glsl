#ifndef SKYIG_TONE_THRESHOLD_GLSL
#define SKYIG_TONE_THRESHOLD_GLSL
// The eye's threshold-versus-intensity function: the smallest luminance difference a viewer
// adapted to La (cd/m^2) can see on a background of La, for rods and cones together. Ward
// Larson, Rushmeier & Piatko 1997 ("A visibility matching tone reproduction operator for high
// dynamic range scenes", IEEE TVCG 3(4)), eq. 7, their fit to Ferwerda et al. 1996 after
// Blackwell's data; in log10 cd/m^2:
//   log dLt = -2.86                                  log La < -3.94
//           = (0.405 log La + 1.6)^2.18 - 2.86       -3.94 <= log La < -1.44
//           = log La - 0.395                         -1.44 <= log La < -0.0184
//           = (0.249 log La + 0.65)^2.7 - 0.72       -0.0184 <= log La < 1.9
//           = log La - 1.255                         1.9 <= log La
// The pieces meet within 0.015 decade (tests/physics/eye/eye_test.cpp checks the joins).
#include "physics/common/constants.glsl"

Float log10ThresholdLuminance(Float log10Adaptation) {
  Float l = log10Adaptation;
  if (l < -3.94) return -2.86;
  if (l < -1.44) return pow(0.405 * l + 1.6, 2.18) - 2.86;
  if (l < -0.0184) return l - 0.395;
  if (l < 1.9) return pow(0.249 * l + 0.65, 2.7) - 0.72;
  return l - 1.255;
}

Float thresholdLuminance(Float adaptationCdM2) {
  return pow(10.0, log10ThresholdLuminance(logTen(max(adaptationCdM2, 1e-12))));
}

#endif
