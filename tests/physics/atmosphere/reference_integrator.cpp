#include "reference_integrator.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace skyig::atmosphere::reference {

LocalMedium localMedium(const Medium& m, const SpectralCoefficients& c, const glm::dvec3& p) {
  const double h = glm::length(p) - m.bottomRadiusM;
  const double rayleigh = std::exp(-h / m.rayleighScaleHeightM);
  const double mie = std::exp(-h / m.mieScaleHeightM);
  const double ozone =
      std::max(0.0, 1.0 - std::abs(h - m.ozoneCentreAltitudeM) / m.ozoneHalfWidthM);
  return {c.rayleighScattering * rayleigh + c.mieExtinction * mie + c.ozoneAbsorption * ozone,
          c.rayleighScattering * rayleigh, c.mieScattering * mie};
}

namespace {

// Smallest positive t with |o + t d| = radius, or -1.
double hitSphere(const glm::dvec3& o, const glm::dvec3& d, double radius, bool far) {
  const double b = glm::dot(o, d);
  const double c = glm::dot(o, o) - radius * radius;
  const double disc = b * b - c;
  if (disc < 0.0) return -1.0;
  const double s = std::sqrt(disc);
  const double t = far ? -b + s : -b - s;
  return t;
}

}  // namespace

double distanceToBoundary(const Medium& m, const Ray& ray, bool* hitsGround) {
  // A ray starting on the ground and pointing down hits it at once (t = 0).
  const double tGround = hitSphere(ray.origin, ray.direction, m.bottomRadiusM, false);
  const bool ground = tGround >= 0.0 && glm::dot(ray.origin, ray.direction) < 0.0;
  if (hitsGround) *hitsGround = ground;
  if (ground) return tGround;
  return std::max(0.0, hitSphere(ray.origin, ray.direction, m.topRadiusM, true));
}

double opticalDepth(const Medium& m, const SpectralCoefficients& c, const Ray& ray,
                    double length, int intervals) {
  if (length <= 0.0) return 0.0;
  const double h = length / intervals;
  double sum = 0.0;
  for (int i = 0; i <= intervals; ++i) {
    const double w = (i == 0 || i == intervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += w * localMedium(m, c, ray.origin + ray.direction * (i * h)).extinction;
  }
  return sum * h / 3.0;
}

double singleScattering(const Medium& m, const SpectralCoefficients& c, const Ray& ray,
                        const glm::dvec3& sun, int steps) {
  const double length = distanceToBoundary(m, ray);
  if (length <= 0.0) return 0.0;
  const double dt = length / steps;
  const double nu = glm::dot(ray.direction, sun);
  const double k = 3.0 / (16.0 * kPi);
  const double phaseR = k * (1.0 + nu * nu);
  const double g = m.miePhaseG;
  const double phaseM = 3.0 / (8.0 * kPi) * (1.0 - g * g) * (1.0 + nu * nu) /
                         ((2.0 + g * g) * std::pow(1.0 + g * g - 2.0 * g * nu, 1.5));
  double radiance = 0.0;
  double depthToViewer = 0.0;
  glm::dvec3 previous = ray.origin;
  for (int i = 0; i < steps; ++i) {
    const glm::dvec3 p = ray.origin + ray.direction * ((i + 0.5) * dt);
    // Optical depth from the viewer, accumulated segment by segment (Simpson per segment).
    depthToViewer += opticalDepth(m, c, Ray{previous, ray.direction}, glm::length(p - previous), 8);
    previous = p;
    const Ray toSun{p, sun};
    bool blocked = false;
    const double sunLength = distanceToBoundary(m, toSun, &blocked);
    if (blocked) continue;
    const double depthToSun = opticalDepth(m, c, toSun, sunLength, 120);
    const LocalMedium local = localMedium(m, c, p);
    radiance += std::exp(-depthToViewer - depthToSun) *
                (local.rayleighScattering * phaseR + local.mieScattering * phaseM) * dt;
  }
  return radiance * c.solarIrradiance;
}

}  // namespace skyig::atmosphere::reference
