#ifndef SKYIG_SKY_ANALYTIC_SKY_GLSL
#define SKYIG_SKY_ANALYTIC_SKY_GLSL
// The analytic sky of Wang, Ji & Zhang 2011 (section 2.2): luminance and chromaticity each
// follow a Perez-form distribution scaled from the zenith value (eq. 7-8, corrected: both divide
// by F(0, theta_s), the value at the zenith for the sun's zenith angle; eq. 7 prints theta_z):
//   F(theta, gamma) = (1 + A exp(B / cos theta)) (K + C exp(D gamma) + E cos^2 gamma)
//   (Y, x, y)(theta, gamma) = (Y, x, y)_zenith F(theta, gamma) / F(0, theta_s).
// K = 1 is Perez et al. 1993 / Preetham et al. 1999; K = 1 - C exp(D pi/2) is the CIE
// standard general sky's indicatrix (physics/analytic/cie_general_sky.glsl), so both models share one
// evaluation. The CPU fills the coefficients per state (physics/analytic/analytic_sky.cpp).
#include "physics/common/constants.glsl"
#include "physics/common/color.glsl"

struct AnalyticSky {
  vec3 a;  // each coefficient holds the (Y, x, y) distributions
  vec3 b;
  vec3 c;
  vec3 d;
  vec3 e;
  vec3 k;
  vec3 zenith;            // (Y in cd/m^2, x, y) at the zenith
  vec3 skySunDirection;   // ENU; the sun the distribution is drawn for (held on the horizon
                          // during twilight, when luminanceScale dims the sky instead)
  Float luminanceScale;   // 1 by day; the twilight decay below the horizon
  vec3 sunDirection;      // ENU unit vector of the true sun (the disc)
  Float cosSunRadius;     // cosine of the solar disc's angular radius
  vec3 sunRadiance;       // disc radiance, linear Rec.709 in cd/m^2
  vec3 groundRadiance;    // Lambertian ground below the horizon, linear Rec.709 in cd/m^2
};

vec3 perezDistribution(IN(AnalyticSky) s, Float cosTheta, Float gamma) {
  Float cosGamma = cos(gamma);
  return (vec3(1.0) + s.a * exp(s.b / max(cosTheta, 1e-4))) *
         (s.k + s.c * exp(s.d * gamma) + s.e * (cosGamma * cosGamma));
}

// Sky light (no sun disc) towards an ENU direction above the horizon, linear Rec.709 cd/m^2.
vec3 analyticSkyLight(IN(AnalyticSky) s, IN(vec3) dir) {
  Float cosTheta = max(dir.z, 0.0);
  Float gamma = acos(clamp(dot(dir, s.skySunDirection), -1.0, 1.0));
  Float thetaS = acos(clamp(s.skySunDirection.z, -1.0, 1.0));
  vec3 yxy = s.zenith * perezDistribution(s, cosTheta, gamma) / perezDistribution(s, 1.0, thetaS);
  vec3 xyz = xyYToXyz(vec3(yxy.y, yxy.z, yxy.x * s.luminanceScale));
  return max(xyzToRec709(xyz), vec3(0.0));
}

// Whether dir falls inside the solar disc (1) or not (0).
Float analyticSunDiscShare(IN(AnalyticSky) s, IN(vec3) dir) {
  return dot(dir, s.sunDirection) >= s.cosSunRadius ? 1.0 : 0.0;
}

// The solar disc, if dir falls inside it.
vec3 analyticSunDisc(IN(AnalyticSky) s, IN(vec3) dir) { return analyticSunDiscShare(s, dir) * s.sunRadiance; }

// What a pixel along dir shows when the sky covers skyShare of it and the sun's disc discShare
// (render/glsl/edge_coverage.glsl): the ground's light and the sky's (a centre just below the
// horizon takes the horizon's), each by its share.
vec3 analyticSkyRadianceShared(IN(AnalyticSky) s, IN(vec3) dir, Float skyShare, Float discShare) {
  vec3 above = normalize(vec3(dir.x, dir.y, max(dir.z, 1e-6)));
  return mix(s.groundRadiance, analyticSkyLight(s, above) + discShare * s.sunRadiance, skyShare);
}

// Everything a view ray meets: sky and sun above the horizon, the ground below it.
vec3 analyticSkyRadiance(IN(AnalyticSky) s, IN(vec3) dir) {
  return analyticSkyRadianceShared(s, dir, dir.z < 0.0 ? 0.0 : 1.0, analyticSunDiscShare(s, dir));
}

#endif
