#include "sky/atmosphere/probe.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace skyig::atmosphere {

namespace {

void check(bool ok, const char* name, double value, const char* expected) {
  if (!ok) {
    std::ostringstream msg;
    msg << "probe: " << name << " = " << value << " is invalid (expected " << expected << ")";
    throw std::invalid_argument(msg.str());
  }
}

const double kReportedWavelengths[] = {440.0, 550.0, 680.0};

nlohmann::json component(const AtmosphereModel& model, const Spectrum& radiance) {
  const SpectralConverter& c = model.converter();
  const glm::dvec3 rgb = c.toRec709(radiance);
  nlohmann::json spectral = nlohmann::json::object();
  for (double w : kReportedWavelengths) {
    spectral[std::to_string(static_cast<int>(w))] = c.at(radiance, w);
  }
  return {{"luminance_cd_m2", c.luminance(radiance)},
          {"rgb_cd_m2", {rgb.r, rgb.g, rgb.b}},
          {"spectral_radiance", spectral}};
}

nlohmann::json transmittanceJson(const AtmosphereModel& model, const Spectrum& t) {
  nlohmann::json j = nlohmann::json::object();
  for (double w : kReportedWavelengths) j[std::to_string(static_cast<int>(w))] = model.converter().at(t, w);
  return j;
}

}  // namespace

glm::dvec3 localDirection(double zenith_deg, double azimuth_deg) {
  const double z = zenith_deg * kDegree;
  const double a = azimuth_deg * kDegree;
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

nlohmann::json probe(const AtmosphereModel& model, const ProbeRequest& request) {
  const Medium& m = model.config().medium;
  check(std::isfinite(request.altitude_m) && request.altitude_m >= 0.0 && request.altitude_m <= 1e8,
        "altitude_m", request.altitude_m, "in [0, 1e8] m");
  check(request.sun_zenith_deg >= 0.0 && request.sun_zenith_deg <= 180.0, "sun_zenith_deg",
        request.sun_zenith_deg, "in [0, 180]");
  check(std::isfinite(request.sun_azimuth_deg), "sun_azimuth_deg", request.sun_azimuth_deg, "finite");
  const glm::dvec3 camera = observerPosition(m, request.altitude_m);
  const glm::dvec3 sun = localDirection(request.sun_zenith_deg, request.sun_azimuth_deg);

  nlohmann::json out;
  out["model"] = "physical";
  out["altitude_m"] = request.altitude_m;
  out["sun"] = {{"zenith_deg", request.sun_zenith_deg}, {"azimuth_deg", request.sun_azimuth_deg}};
  out["views"] = nlohmann::json::array();
  for (const ProbeView& v : request.views) {
    check(v.zenith_deg >= 0.0 && v.zenith_deg <= 180.0, "view zenith_deg", v.zenith_deg, "in [0, 180]");
    check(std::isfinite(v.azimuth_deg), "view azimuth_deg", v.azimuth_deg, "finite");
    const glm::dvec3 view = localDirection(v.zenith_deg, v.azimuth_deg);
    Spectrum transmittance;
    const Spectrum sky = model.skyRadiance(camera, view, sun, &transmittance);
    nlohmann::json j = {{"zenith_deg", v.zenith_deg}, {"azimuth_deg", v.azimuth_deg}};
    j["sky"] = component(model, sky);
    const Spectrum disc = model.sunDiscRadiance(camera, view, sun);
    bool on_disc = false;
    for (double d : disc) on_disc = on_disc || d > 0.0;
    j["sun"] = on_disc ? component(model, disc) : nlohmann::json(nullptr);
    // The ground, if the ray meets it: its reflection of sun and sky, attenuated on the way
    // (the light scattered in on the way is part of "sky").
    const double r = glm::length(camera);
    const double rmu = glm::dot(camera, view);
    const double disc_ground = rmu * rmu - r * r + m.bottom_radius_m * m.bottom_radius_m;
    if (rmu < 0.0 && disc_ground >= 0.0) {
      const glm::dvec3 point = camera + view * (-rmu - std::sqrt(disc_ground));
      Spectrum t_ground;
      const Spectrum total = model.groundRadiance(camera, point, sun, &t_ground);
      const Spectrum in_scatter = model.skyRadianceToPoint(camera, point, sun);
      Spectrum reflected(total.size());
      for (std::size_t i = 0; i < total.size(); ++i) reflected[i] = std::max(total[i] - in_scatter[i], 0.0);
      j["ground"] = component(model, reflected);
      transmittance = t_ground;
    } else {
      j["ground"] = nullptr;
    }
    j["transmittance"] = transmittanceJson(model, transmittance);
    out["views"].push_back(j);
  }
  if (request.irradiance) {
    const glm::dvec3 up(0.0, 0.0, 1.0);
    out["irradiance"] = {
        {"direct_sun_lux", model.converter().luminance(model.sunIrradiance(camera, up, sun))},
        {"sky_lux", model.converter().luminance(model.skyIrradiance(camera, up, sun))}};
  }
  return out;
}

}  // namespace skyig::atmosphere
