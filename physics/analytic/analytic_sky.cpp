#include "physics/analytic/analytic_sky.h"

#include "physics/analytic/cie_sky_types.h"
#include "physics/common/hemisphere_grid.h"
#include "physics/analytic/analytic_physics.h"
#include "physics/common/units.h"

#include <cmath>
#include <numbers>

namespace skyig::sky {

namespace {

constexpr double kPi = std::numbers::pi;
using skyig::kDeg;

// Below the horizon the analytic models have no data. The distribution is held at a sun on
// the horizon and dimmed by 0.4 decades per degree of depression: the slope of the measured
// horizontal illuminance of a clear twilight between sunset (~700 lx) and the end of civil
// (3.4 lx) and nautical (0.008 lx) twilight (Bond & Henderson 1963, "The conquest of
// darkness", the values tabulated by the US Naval Observatory). The physical atmosphere
// model supersedes this.
constexpr double kTwilightDecadesPerDegree = 0.4;

// Overcast zenith luminance, Krochmann & Seidl 1974 ("Quantitative data on daylight for
// illuminating engineering", Lighting Res. Technol. 6): L_z = 123 + 8600 sin(h) cd/m^2.
double overcastZenithLuminance(double sunAltitude) {
  return 123.0 + 8600.0 * std::sin(std::max(sunAltitude, 0.0));
}

// Kasten & Young 1989 relative optical air mass, valid to the horizon (38.1 at h = 0).
double airMass(double altitude) {
  const double zenithDeg = 90.0 - std::max(altitude, 0.0) / kDeg;
  return 1.0 / (std::cos(zenithDeg * kDeg) + 0.50572 * std::pow(96.07995 - zenithDeg, -1.6364));
}

// Direct-beam transmittance at the Rec.709 primaries (taken at 680, 550, 440 nm). Rayleigh
// optical depth from Bruneton's sea-level coefficients (5.8, 13.5, 33.1)e-6 /m times the 8 km
// scale height; aerosol depth from Preetham's definition of turbidity, T = (tau_R + tau_A) /
// tau_R at 550 nm, with an Angstrom exponent of 1.3.
glm::dvec3 beamTransmittance(double turbidity, double altitude) {
  const glm::dvec3 rayleigh = glm::dvec3(5.8e-6, 13.5e-6, 33.1e-6) * 8000.0;
  const glm::dvec3 lambda(680.0, 550.0, 440.0);
  const glm::dvec3 aerosol = (turbidity - 1.0) * rayleigh.y * glm::pow(lambda / 550.0, glm::dvec3(-1.3));
  return glm::exp(-airMass(altitude) * (rayleigh + aerosol));
}

// Colour of the sun above the atmosphere, a 5778 K Planckian radiator, with Y = 1.
glm::dvec3 extraterrestrialSunColour() {
  const glm::dvec2 xy = shader::planckianChromaticity(5778.0);
  return shader::xyzToRec709(shader::xyYToXyz(glm::dvec3(xy, 1.0)));
}

shader::AnalyticSky toShader(const AnalyticSkyParams& p) {
  return shader::AnalyticSky{p.a, p.b, p.c, p.d, p.e, p.k, p.zenith, p.skySunDirection,
                             p.luminanceScale, p.sunDirection, p.cosSunRadius, p.sunRadiance,
                             p.groundRadiance};
}

// Luminance distribution (the Y channel) and zenith luminance of the model.
void setLuminanceDistribution(const SkyConditions& c, double thetaS, double sunAltitude,
                              AnalyticSkyParams& p) {
  glm::dvec3 a, b, cc, d, e;
  shader::preethamPerezCoefficients(c.turbidity, a, b, cc, d, e);
  p.a = a;
  p.b = b;
  p.c = cc;
  p.d = d;
  p.e = e;
  p.k = glm::dvec3(1.0);
  p.zenith = glm::dvec3(shader::preethamZenithLuminance(c.turbidity, thetaS),
                        shader::preethamZenithChromaticity(c.turbidity, thetaS));
  if (c.model != SkyModel::Cie) return;

  const CieSkyType& t = cieSkyType(c.cieType);
  p.a.x = t.a;
  p.b.x = t.b;
  p.c.x = t.c;
  p.d.x = t.d;
  p.e.x = t.e;
  p.k.x = 1.0 - t.c * std::exp(t.d * kPi * 0.5);  // the CIE indicatrix's constant term
  if (t.overcast) {
    // Overcast skies: uniform D65 chromaticity (CIE 15:2004) at the overcast level.
    p.zenith = glm::dvec3(overcastZenithLuminance(sunAltitude), 0.3127, 0.3290);
    p.a.y = p.a.z = p.c.y = p.c.z = p.e.y = p.e.z = 0.0;
    p.k.y = p.k.z = 1.0;
  }
}

SkyLighting integrateLighting(const AnalyticSkyParams& p) {
  constexpr int kMu = 64, kPhi = 128;
  SkyLighting lighting;
  double luminanceSum = 0.0;
  const shader::AnalyticSky sky = toShader(p);
  forEachHemisphereDirection(kMu, kPhi, [&](const glm::dvec3& dir) {
    const glm::dvec3 l = shader::analyticSkyLight(sky, dir);
    lighting.diffuseHorizontal += l * dir.z;
    luminanceSum += shader::rec709Luminance(l);
  });
  const double dOmega = (1.0 / kMu) * (2.0 * kPi / kPhi);
  lighting.diffuseHorizontal *= dOmega;
  lighting.meanSkyLuminance = luminanceSum * dOmega / (2.0 * kPi);
  return lighting;
}

}  // namespace

glm::dvec3 enuDirection(double azimuth, double altitude) {
  return {std::cos(altitude) * std::sin(azimuth), std::cos(altitude) * std::cos(azimuth), std::sin(altitude)};
}

AnalyticSkyState makeAnalyticSky(const SkyConditions& c, double sunAzimuth, double sunAltitude,
                                 std::optional<double> sunApparentAltitude) {
  AnalyticSkyState state;
  AnalyticSkyParams& p = state.params;
  const double skyAltitude = std::max(sunAltitude, 0.0);
  p.skySunDirection = enuDirection(sunAzimuth, skyAltitude);
  p.luminanceScale = sunAltitude < 0.0 ? std::pow(10.0, kTwilightDecadesPerDegree * sunAltitude / kDeg) : 1.0;
  setLuminanceDistribution(c, kPi * 0.5 - skyAltitude, sunAltitude, p);

  p.sunDirection = enuDirection(sunAzimuth, sunApparentAltitude.value_or(sunAltitude));
  p.cosSunRadius = std::cos(shader::SUN_ANGULAR_RADIUS);
  const bool sunVisible = c.model != SkyModel::Cie || cieSkyType(c.cieType).sunVisible;
  const double solidAngle = 2.0 * kPi * (1.0 - p.cosSunRadius);
  const double normalIlluminance = shader::SOLAR_ILLUMINANCE_LX / (c.sunDistanceAu * c.sunDistanceAu);
  const glm::dvec3 sunIlluminance =
      normalIlluminance * extraterrestrialSunColour() * beamTransmittance(c.turbidity, sunAltitude);
  p.sunRadiance = sunVisible ? sunIlluminance / solidAngle : glm::dvec3(0.0);

  state.lighting = integrateLighting(p);
  state.lighting.directHorizontal = sunVisible ? sunIlluminance * std::max(std::sin(sunAltitude), 0.0) : glm::dvec3(0.0);
  p.groundRadiance = c.groundAlbedo / kPi * (state.lighting.directHorizontal + state.lighting.diffuseHorizontal);
  return state;
}

glm::dvec3 analyticSkyRadiance(const AnalyticSkyParams& params, const glm::dvec3& direction) {
  return shader::analyticSkyRadiance(toShader(params), direction);
}

glm::dvec3 analyticSkyLightOnly(const AnalyticSkyParams& params, const glm::dvec3& direction) {
  return direction.z < 0.0 ? glm::dvec3(0.0) : shader::analyticSkyLight(toShader(params), direction);
}

glm::dvec3 analyticSunDiscOnly(const AnalyticSkyParams& params, const glm::dvec3& direction) {
  return direction.z < 0.0 ? glm::dvec3(0.0) : shader::analyticSunDisc(toShader(params), direction);
}

}  // namespace skyig::sky
