#ifndef SKYIG_TONE_GLARE_GLSL
#define SKYIG_TONE_GLARE_GLSL
// Veiling glare: light of a bright source scattered inside the eye (cornea, lens, fundus),
// seen as a luminance veil around it. The CIE General Disability Glare equation (CIE 146:2002;
// Vos 2003, "On the cause of disability glare and its dependence on glare angle, age and ocular
// pigmentation", Clin Exp Optom 86(6)) gives the veil per unit illuminance at the eye from a
// point source theta degrees off the line of sight, for an observer of age A (years) and
// ocular pigmentation p (0 very dark eyes, 0.5 brown, 1 blue-green):
//   L_veil / E_glare = 10 / theta^3 + (5 / theta^2 + 0.1 p / theta) (1 + (A / 62.5)^4)
//                      + 0.0025 p           [cd/m^2 per lux], valid 0.1 deg < theta < 100 deg.
// Between 1 and 30 deg it is the classic Stiles-Holladay 10 / theta^2 within the spread of
// observers. It is what the eye adds to the scene, so the display path adds it to the world's
// radiance before the tone mapping (the sun then reads as the brightest thing in the frame,
// wrapped in its own light) and the EXR, the scene in cd/m^2, does not.
#include "physics/common/constants.glsl"

// The equation as a cubic in 1 / theta: L_veil / E = ((a / t + b) / t + c) / t + d, its
// coefficients (a, b, c, d) those of the observer, so that a pass evaluating it for every pixel
// computes the age factor once per frame rather than a pow per pixel and source.
vec4 veilCoefficients(Float ageYears, Float pigmentation) {
  Float age = 1.0 + pow(ageYears / 62.5, 4.0);
  return vec4(10.0, 5.0 * age, 0.1 * pigmentation * age, 0.0025 * pigmentation);
}

// The glare of a source seen at the eye as a disc of angular radius `radiusDeg`: inside the
// disc and below the equation's 0.1 deg it is held at its value at max(radius, 0.1 deg).
Float veilPerLux(Float thetaDeg, Float radiusDeg, IN(vec4) k) {
  Float it = 1.0 / max(thetaDeg, max(radiusDeg, 0.1));
  return ((k.x * it + k.y) * it + k.z) * it + k.w;
}

Float veilingLuminancePerLux(Float thetaDeg, Float radiusDeg, Float ageYears, Float pigmentation) {
  return veilPerLux(thetaDeg, radiusDeg, veilCoefficients(ageYears, pigmentation));
}

#endif
