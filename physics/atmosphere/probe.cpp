#include "physics/atmosphere/probe.h"

#include <algorithm>
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

std::array<double, kProbeWavelengthsNm.size()> atProbeWavelengths(const AtmosphereModel& model, const Spectrum& s) {
  std::array<double, kProbeWavelengthsNm.size()> out{};
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = model.converter().at(s, kProbeWavelengthsNm[i]);
  return out;
}

SpectralProbeLight light(const AtmosphereModel& model, const Spectrum& radiance) {
  const SpectralConverter& c = model.converter();
  SpectralProbeLight out;
  out.luminance = c.luminance(radiance);
  out.rec709 = c.toRec709(radiance);
  out.spectralRadiance = atProbeWavelengths(model, radiance);
  return out;
}

}  // namespace

ProbeIrradiance horizontalIrradiance(const AtmosphereModel& model, const glm::dvec3& camera, const glm::dvec3& sun) {
  const glm::dvec3 up(0.0, 0.0, 1.0);
  return {model.converter().luminance(model.sunIrradiance(camera, up, sun)),
          model.converter().luminance(model.skyIrradiance(camera, up, sun))};
}

glm::dvec3 localDirection(double zenithDeg, double azimuthDeg) {
  const double z = zenithDeg * kDegree;
  const double a = azimuthDeg * kDegree;
  return {std::sin(z) * std::sin(a), std::sin(z) * std::cos(a), std::cos(z)};
}

ProbeResult probe(const AtmosphereModel& model, const ProbeRequest& request) {
  const Medium& m = model.config().medium;
  check(std::isfinite(request.altitudeM) && request.altitudeM >= 0.0 && request.altitudeM <= 1e8,
        "altitude_m", request.altitudeM, "in [0, 1e8] m");
  check(request.sunZenithDeg >= 0.0 && request.sunZenithDeg <= 180.0, "sun_zenith_deg",
        request.sunZenithDeg, "in [0, 180]");
  check(std::isfinite(request.sunAzimuthDeg), "sun_azimuth_deg", request.sunAzimuthDeg, "finite");
  const glm::dvec3 camera = observerPosition(m, request.altitudeM);
  const glm::dvec3 sun = localDirection(request.sunZenithDeg, request.sunAzimuthDeg);

  ProbeResult out;
  out.altitudeM = request.altitudeM;
  out.sunZenithDeg = request.sunZenithDeg;
  out.sunAzimuthDeg = request.sunAzimuthDeg;
  for (const ProbeView& v : request.views) {
    check(v.zenithDeg >= 0.0 && v.zenithDeg <= 180.0, "view zenith_deg", v.zenithDeg, "in [0, 180]");
    check(std::isfinite(v.azimuthDeg), "view azimuth_deg", v.azimuthDeg, "finite");
    const glm::dvec3 view = localDirection(v.zenithDeg, v.azimuthDeg);
    ProbeViewResult r;
    r.view = v;
    Spectrum transmittance;
    r.sky = light(model, model.skyRadiance(camera, view, sun, &transmittance));
    const Spectrum disc = model.sunDiscRadiance(camera, view, sun);
    if (std::any_of(disc.begin(), disc.end(), [](double d) { return d > 0.0; })) r.sun = light(model, disc);
    // The ground, if the ray meets it: its reflection of sun and sky, attenuated on the way
    // (the light scattered in on the way is part of "sky").
    const double radius = glm::length(camera);
    const double rmu = glm::dot(camera, view);
    const double discGround = rmu * rmu - radius * radius + m.bottomRadiusM * m.bottomRadiusM;
    if (rmu < 0.0 && discGround >= 0.0) {
      const glm::dvec3 point = camera + view * (-rmu - std::sqrt(discGround));
      Spectrum tGround;
      const Spectrum total = model.groundRadiance(camera, point, sun, &tGround);
      const Spectrum inScatter = model.skyRadianceToPoint(camera, point, sun);
      Spectrum reflected(total.size());
      for (std::size_t i = 0; i < total.size(); ++i) reflected[i] = std::max(total[i] - inScatter[i], 0.0);
      r.ground = light(model, reflected);
      transmittance = tGround;
    }
    r.transmittance = atProbeWavelengths(model, transmittance);
    out.views.push_back(r);
  }
  if (request.irradiance) {
    out.irradiance = horizontalIrradiance(model, camera, sun);
  }
  return out;
}

}  // namespace skyig::atmosphere
