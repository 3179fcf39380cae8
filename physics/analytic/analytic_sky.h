#pragma once
// The analytic sky of a state (Wang, Ji & Zhang 2011, section 2.2: the Perez model of Perez,
// Seals & Michalsky 1993 as Preetham, Shirley & Smits 1999 and CIE S 011 use it) on the CPU
// side: the per-state coefficients the sky shader needs, and the lighting quantities derived
// from the same model (horizontal illuminance for the ground, the eye's adaptation luminance).
#include "physics/common/sky_conditions.h"

#include <glm/glm.hpp>

#include <optional>

namespace skyig::sky {

// Mirrors the GLSL struct AnalyticSky (physics/analytic/analytic_sky.glsl) field by field; the
// struct itself is TU-local in C++ (physics/physics.h), so this is what crosses files.
struct AnalyticSkyParams {
  glm::dvec3 a{0.0}, b{-1.0}, c{0.0}, d{-1.0}, e{0.0}, k{1.0};
  glm::dvec3 zenith{0.0, 0.3127, 0.3290};  // (Y cd/m^2, x, y)
  glm::dvec3 skySunDirection{0.0, 0.0, 1.0};
  double luminanceScale = 1.0;
  glm::dvec3 sunDirection{0.0, 0.0, 1.0};
  double cosSunRadius = 1.0;
  glm::dvec3 sunRadiance{0.0};
  glm::dvec3 groundRadiance{0.0};
};

struct SkyLighting {
  glm::dvec3 directHorizontal{0.0};   // sun on a horizontal surface, Rec.709 with Y in lux
  glm::dvec3 diffuseHorizontal{0.0};  // sky on a horizontal surface, Rec.709 with Y in lux
  double meanSkyLuminance = 0.0;      // over the upper hemisphere, cd/m^2 (solid-angle mean)
};

struct AnalyticSkyState {
  AnalyticSkyParams params;
  SkyLighting lighting;
};

// Builds the sky of the conditions for a sun at the given azimuth (from north through east)
// and airless altitude (radians), including the ground it lights; the disc is drawn at the
// apparent (refracted) altitude when given.
AnalyticSkyState makeAnalyticSky(const SkyConditions& conditions, double sunAzimuth, double sunAltitude,
                                 std::optional<double> sunApparentAltitude = std::nullopt);

// Evaluations of the shader code in double precision (physics/physics.h): linear Rec.709
// radiance in cd/m^2 towards an ENU unit direction.
glm::dvec3 analyticSkyRadiance(const AnalyticSkyParams& params, const glm::dvec3& direction);
glm::dvec3 analyticSkyLightOnly(const AnalyticSkyParams& params, const glm::dvec3& direction);
glm::dvec3 analyticSunDiscOnly(const AnalyticSkyParams& params, const glm::dvec3& direction);

// Direction in ENU of an azimuth (from north through east) and altitude, radians.
glm::dvec3 enuDirection(double azimuth, double altitude);

}  // namespace skyig::sky
