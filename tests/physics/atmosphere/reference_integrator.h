#pragma once
// Independent references for the atmosphere tests: straightforward numerical integration in
// Cartesian coordinates, at one wavelength, from the Medium alone. It shares no code with the
// GLSL physics (physics/atmosphere/) or the tables, so agreement is evidence, not tautology.
#include <glm/vec3.hpp>

#include "physics/atmosphere/medium.h"

namespace skyig::atmosphere::reference {

struct Ray {
  glm::dvec3 origin;
  glm::dvec3 direction;  // unit
};

// Extinction coefficient (m^-1) at a point, and its scattering parts.
struct LocalMedium {
  double extinction;
  double rayleighScattering;
  double mieScattering;
};
LocalMedium localMedium(const Medium& m, const SpectralCoefficients& c, const glm::dvec3& p);

// Distance along the ray to the top of the atmosphere, or to the ground if it hits it first.
double distanceToBoundary(const Medium& m, const Ray& ray, bool* hitsGround = nullptr);

// Optical depth over [0, length] by composite Simpson with `intervals` (even) intervals.
double opticalDepth(const Medium& m, const SpectralCoefficients& c, const Ray& ray,
                    double length, int intervals = 20000);

// Single-scattered radiance (W m^-2 sr^-1 nm^-1) reaching the ray's origin from its
// direction (light travelling along -direction), sun along `sun` (unit): a ray march with
// `steps` midpoint steps, each with its own optical depths to the viewer and to the sun, the
// sun treated as a point (no disc) and its light cut by the ground sphere.
double singleScattering(const Medium& m, const SpectralCoefficients& c, const Ray& ray,
                        const glm::dvec3& sun, int steps = 2000);

}  // namespace skyig::atmosphere::reference
