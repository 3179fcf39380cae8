#pragma once
// What `skyig probe` reports for the physical sky (docs/atmosphere.md), computed on the CPU from
// a model: per view direction, the light scattered into the ray (sky), the solar disc (sun)
// and the reflected ground light (ground), each as luminance, linear Rec.709 scaled so Y is
// cd/m^2, and spectral radiance at 440/550/680 nm; the ray's transmittance; optionally the
// direct-sun and sky illuminance on a horizontal surface at the observer. Plain values: the
// CLI (commands/probe_json.h) parses the flags and prints them as JSON.
#include <array>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "physics/atmosphere/model.h"

namespace skyig::atmosphere {

struct ProbeView {
  double zenithDeg;
  double azimuthDeg;  // from north through east
};

struct ProbeRequest {
  double altitudeM = 0.0;
  double sunZenithDeg = 30.0;
  double sunAzimuthDeg = 180.0;
  std::vector<ProbeView> views;
  bool irradiance = false;
};

// The wavelengths (nm) the probe reports spectral values at: the paper's three.
inline constexpr std::array<double, 3> kProbeWavelengthsNm = {440.0, 550.0, 680.0};

// One light along a view: luminance (cd/m^2) and linear Rec.709 scaled so Y is cd/m^2.
struct ProbeLight {
  double luminance = 0.0;
  glm::dvec3 rec709{0.0};
};

// A light the model computes spectrally: also its spectral radiance (W m^-2 sr^-1 nm^-1) at
// kProbeWavelengthsNm; its luminance is that of the spectrum (CIE Y).
struct SpectralProbeLight : ProbeLight {
  std::array<double, kProbeWavelengthsNm.size()> spectralRadiance{};
};

struct ProbeViewResult {
  ProbeView view;
  SpectralProbeLight sky;                   // scattered into the ray
  std::optional<SpectralProbeLight> sun;    // the solar disc, when the view is on it
  std::optional<SpectralProbeLight> ground; // the ground's reflection, when the ray meets it
  // Of the whole ray to space, or to the ground point when it meets the ground (0 m from the
  // ground: 1), at kProbeWavelengthsNm.
  std::array<double, kProbeWavelengthsNm.size()> transmittance{};
};

// On a horizontal surface at the observer, lux.
struct ProbeIrradiance {
  double directSunLux = 0.0;
  double skyLux = 0.0;
};

struct ProbeResult {
  double altitudeM = 0.0;
  double sunZenithDeg = 0.0;
  double sunAzimuthDeg = 0.0;
  std::vector<ProbeViewResult> views;        // in the request's order
  std::optional<ProbeIrradiance> irradiance;  // when the request asks for it
};

// The direct sun's and the sky's illuminance on a horizontal surface at `camera` (metres from
// the planet's centre, on the +z axis) for a sun in the ENU direction `sun`: what the probe
// reports with --irradiance, and what a host lights its terrain with (sky/client_light.h).
ProbeIrradiance horizontalIrradiance(const AtmosphereModel& model, const glm::dvec3& camera, const glm::dvec3& sun);

// Local frame at the observer: x east, y north, z up (the observer on the +z axis).
glm::dvec3 localDirection(double zenithDeg, double azimuthDeg);

// Throws std::invalid_argument naming a bad value (angles out of range, altitude below the
// ground or not finite).
ProbeResult probe(const AtmosphereModel& model, const ProbeRequest& request);

}  // namespace skyig::atmosphere
