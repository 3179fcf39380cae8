#pragma once
// What `skyig probe` reports for the physical sky (docs/atmosphere.md), computed on the CPU from
// a model: per view direction, the light scattered into the ray (sky), the solar disc (sun)
// and the reflected ground light (ground), each as luminance, linear Rec.709 scaled so Y is
// cd/m^2, and spectral radiance at 440/550/680 nm; the ray's transmittance; optionally the
// direct-sun and sky illuminance on a horizontal surface at the observer. The CLI (services/)
// parses the flags and prints this JSON.
#include <nlohmann/json.hpp>

#include <vector>

#include "sky/atmosphere/model.h"

namespace skyig::atmosphere {

struct ProbeView {
  double zenith_deg;
  double azimuth_deg;  // from north through east
};

struct ProbeRequest {
  double altitude_m = 0.0;
  double sun_zenith_deg = 30.0;
  double sun_azimuth_deg = 180.0;
  std::vector<ProbeView> views;
  bool irradiance = false;
};

// Local frame at the observer: x east, y north, z up (the observer on the +z axis).
glm::dvec3 localDirection(double zenith_deg, double azimuth_deg);

// Throws std::invalid_argument naming a bad value (angles out of range, altitude below the
// ground or not finite).
nlohmann::json probe(const AtmosphereModel& model, const ProbeRequest& request);

}  // namespace skyig::atmosphere
