#ifndef SKYIG_SKY_PREETHAM_GLSL
#define SKYIG_SKY_PREETHAM_GLSL
// Preetham, Shirley & Smits 1999, "A practical analytic model for daylight", appendix A.2:
// absolute zenith luminance and chromaticity, and the turbidity-dependent coefficients of the
// Perez et al. 1993 distribution for Y, x and y. T is the turbidity (1 = pure air; Preetham
// define it as the ratio of total to molecular optical thickness), thetaS the sun's zenith
// angle in radians. Valid for the sun above the horizon and T in about [2, 10].
#include "physics/common/constants.glsl"

// Zenith luminance in cd/m^2 (the paper gives kcd/m^2).
Float preethamZenithLuminance(Float turbidity, Float thetaS) {
  Float chi = (4.0 / 9.0 - turbidity / 120.0) * (PI - 2.0 * thetaS);
  return 1000.0 * ((4.0453 * turbidity - 4.9710) * tan(chi) - 0.2155 * turbidity + 2.4192);
}

// Zenith chromaticity (x_z, y_z): [T^2 T 1] M [thetaS^3 thetaS^2 thetaS 1]^T.
vec2 preethamZenithChromaticity(Float turbidity, Float thetaS) {
  vec4 th = vec4(thetaS * thetaS * thetaS, thetaS * thetaS, thetaS, 1.0);
  vec3 tt = vec3(turbidity * turbidity, turbidity, 1.0);
  vec3 mx = vec3(dot(vec4(0.00166, -0.00375, 0.00209, 0.0), th),
                 dot(vec4(-0.02903, 0.06377, -0.03202, 0.00394), th),
                 dot(vec4(0.11693, -0.21196, 0.06052, 0.25886), th));
  vec3 my = vec3(dot(vec4(0.00275, -0.00610, 0.00317, 0.0), th),
                 dot(vec4(-0.04214, 0.08970, -0.04153, 0.00516), th),
                 dot(vec4(0.15346, -0.26756, 0.06670, 0.26688), th));
  return vec2(dot(tt, mx), dot(tt, my));
}

// Perez coefficients A..E, each a vec3 holding the (Y, x, y) distributions.
void preethamPerezCoefficients(Float t, OUT(vec3) a, OUT(vec3) b, OUT(vec3) c, OUT(vec3) d,
                               OUT(vec3) e) {
  a = vec3(0.1787 * t - 1.4630, -0.0193 * t - 0.2592, -0.0167 * t - 0.2608);
  b = vec3(-0.3554 * t + 0.4275, -0.0665 * t + 0.0008, -0.0950 * t + 0.0092);
  c = vec3(-0.0227 * t + 5.3251, -0.0004 * t + 0.2125, -0.0079 * t + 0.2102);
  d = vec3(0.1206 * t - 2.5771, -0.0641 * t - 0.8989, -0.0441 * t - 1.6537);
  e = vec3(-0.0670 * t + 0.3703, -0.0033 * t + 0.0452, -0.0109 * t + 0.0529);
}

#endif
