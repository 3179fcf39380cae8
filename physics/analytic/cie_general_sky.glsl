#ifndef SKYIG_SKY_CIE_GENERAL_SKY_GLSL
#define SKYIG_SKY_CIE_GENERAL_SKY_GLSL
// CIE standard general sky (CIE S 011/E:2003 = ISO 15469:2004), the Perez-form relative
// luminance of Wang, Ji & Zhang 2011, eq. 6-7 (corrected: the last term of eq. 6 is
// e cos^2(chi), printed "Ec cos^2", and eq. 7 divides by the same function at the zenith with
// the sun's zenith angle, F(0, theta_s), printed F(0, theta_z)). Coefficients a..e of the 15
// types are in physics/analytic/cie_sky_types.cpp.
#include "physics/common/constants.glsl"

struct CieSkyCoefficients {
  Float a;  // gradation: 1 + a exp(b / cos Z)
  Float b;
  Float c;  // indicatrix: 1 + c (exp(d chi) - exp(d pi/2)) + e cos^2 chi
  Float d;
  Float e;
};

// phi(Z): luminance gradation with zenith angle; 1 at the horizon since b < 0 for every type.
Float cieGradation(IN(CieSkyCoefficients) k, Float cosZ) {
  return 1.0 + k.a * exp(k.b / max(cosZ, 1e-4));
}

// f(chi): scattering indicatrix with angular distance chi (radians) from the sun.
Float cieIndicatrix(IN(CieSkyCoefficients) k, Float chi) {
  Float cosChi = cos(chi);
  return 1.0 + k.c * (exp(k.d * chi) - exp(k.d * PI * 0.5)) + k.e * cosChi * cosChi;
}

// L(Z, chi) / L_zenith = f(chi) phi(Z) / (f(Zs) phi(0)).
Float cieRelativeLuminance(IN(CieSkyCoefficients) k, Float cosZ, Float chi, Float sunZenith) {
  return cieIndicatrix(k, chi) * cieGradation(k, cosZ) /
         (cieIndicatrix(k, sunZenith) * cieGradation(k, 1.0));
}

#endif
