#include "reference_integrator.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace skyig::atmosphere::reference {

LocalMedium localMedium(const Medium& m, const SpectralCoefficients& c, const glm::dvec3& p) {
  const double h = glm::length(p) - m.bottom_radius_m;
  const double rayleigh = std::exp(-h / m.rayleigh_scale_height_m);
  const double mie = std::exp(-h / m.mie_scale_height_m);
  const double ozone =
      std::max(0.0, 1.0 - std::abs(h - m.ozone_center_altitude_m) / m.ozone_half_width_m);
  return {c.rayleigh_scattering * rayleigh + c.mie_extinction * mie + c.ozone_absorption * ozone,
          c.rayleigh_scattering * rayleigh, c.mie_scattering * mie};
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

double distanceToBoundary(const Medium& m, const Ray& ray, bool* hits_ground) {
  // A ray starting on the ground and pointing down hits it at once (t = 0).
  const double t_ground = hitSphere(ray.origin, ray.direction, m.bottom_radius_m, false);
  const bool ground = t_ground >= 0.0 && glm::dot(ray.origin, ray.direction) < 0.0;
  if (hits_ground) *hits_ground = ground;
  if (ground) return t_ground;
  return std::max(0.0, hitSphere(ray.origin, ray.direction, m.top_radius_m, true));
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
  const double phase_r = k * (1.0 + nu * nu);
  const double g = m.mie_phase_g;
  const double phase_m = 3.0 / (8.0 * kPi) * (1.0 - g * g) * (1.0 + nu * nu) /
                         ((2.0 + g * g) * std::pow(1.0 + g * g - 2.0 * g * nu, 1.5));
  double radiance = 0.0;
  double depth_to_viewer = 0.0;
  glm::dvec3 previous = ray.origin;
  for (int i = 0; i < steps; ++i) {
    const glm::dvec3 p = ray.origin + ray.direction * ((i + 0.5) * dt);
    // Optical depth from the viewer, accumulated segment by segment (Simpson per segment).
    depth_to_viewer += opticalDepth(m, c, Ray{previous, ray.direction}, glm::length(p - previous), 8);
    previous = p;
    const Ray to_sun{p, sun};
    bool blocked = false;
    const double sun_length = distanceToBoundary(m, to_sun, &blocked);
    if (blocked) continue;
    const double depth_to_sun = opticalDepth(m, c, to_sun, sun_length, 120);
    const LocalMedium local = localMedium(m, c, p);
    radiance += std::exp(-depth_to_viewer - depth_to_sun) *
                (local.rayleigh_scattering * phase_r + local.mie_scattering * phase_m) * dt;
  }
  return radiance * c.solar_irradiance;
}

}  // namespace skyig::atmosphere::reference
