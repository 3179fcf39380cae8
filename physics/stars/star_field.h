#pragma once
// The point sources of one SkyState, as the observer sees them: every catalogue star and the
// five naked-eye planets at their apparent (refracted) directions, with their illuminance at
// the eye after extinction and reddening by the atmosphere, the twinkle and the host's star
// field intensity. Built on the worker once per state, drawn by render/passes/night/star_pass.h and read by
// the night probe (physics/stars/star_luminance.h).
#include "ephemeris/ephemeris.h"
#include "physics/atmosphere/extinction_profile.h"
#include "physics/stars/star_catalogue.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace skyig::sky::night {

struct PointSource {
  glm::dvec3 direction{0.0, 0.0, 1.0};  // apparent (refracted) ENU unit vector
  glm::dvec3 rec709Lux{0.0};            // linear Rec.709 illuminance on a surface facing it, lux
  double illuminanceLux = 0.0;          // its luminance-weighted sum (Y)
  double temperatureK = 5800.0;         // of its colour above the atmosphere (star_colour.h)
};

struct StarField {
  std::vector<PointSource> stars;    // above the horizon, with any light left
  std::vector<PointSource> planets;  // Mercury, Venus, Mars, Jupiter, Saturn, those visible
};

// Approximate B-V of the planets' integrated light, as commonly tabulated (e.g. Allen's
// Astrophysical Quantities), good to about 0.1: Mercury, Venus, Mars, Jupiter, Saturn. A
// blackbody of the eq. 12 temperature only approximates reflected sunlight.
inline constexpr double kPlanetBMinusV[5] = {0.93, 0.82, 1.36, 0.83, 1.04};

struct StarFieldOptions {
  double intensity = 1.0;       // the host's star field intensity (CIGI percentage / 100), [0, 1]
  double timeS = 0.0;           // simulation time driving the twinkle
  bool scintillation = true;
};

// Stars (when `catalogue` is non-null) and planets seen at the ephemeris' time and place
// (refraction at its observer's pressure and temperature), dimmed by `extinction`.
// Throws std::invalid_argument for an intensity outside [0, 1] or NaN.
StarField buildStarField(const StarCatalogue* catalogue, const ephemeris::SkyEphemeris& sky,
                         const atmosphere::ExtinctionProfile& extinction, const StarFieldOptions& options);

// The illuminance of all the field's stars and planets on a horizontal surface at the observer
// (linear Rec.709 lux per channel): the sum of each one's illuminance times the sine of its
// altitude. About 3e-4 lux for the whole sky of a dark site (Roach & Gordon 1973: the
// integrated starlight is of the order of the zodiacal light's).
glm::dvec3 horizontalIlluminance(const StarField& field);

// The apparent direction of an airless ENU unit vector, lifted by refraction (Saemundsson) at
// `pressureHpa` and `temperatureC`, azimuth unchanged.
glm::dvec3 refractedDirection(const glm::dvec3& airless, double pressureHpa, double temperatureC);

}  // namespace skyig::sky::night
