#include "sky/fog_state.h"

#include "physics/atmosphere/physical_camera.h"

#include <cmath>

namespace skyig::sky {

namespace {

// Sun (or moon) and sky on a horizontal surface at radius r above the model's origin, Rec.709 lux.
glm::dvec3 irradianceAt(const atmosphere::AtmosphereModel& model, double r, const glm::dvec3& light) {
  const glm::dvec3 point(0.0, 0.0, r), up(0.0, 0.0, 1.0);
  return model.converter().toRec709(model.sunIrradiance(point, up, light)) +
         model.converter().toRec709(model.skyIrradiance(point, up, light));
}

// The layers lit at their tops by sun * sunWeight + moon * moonWeight.
std::array<weather::FogLayer, 2> litBy(const FogState& fog, double sunWeight, double moonWeight) {
  std::array<weather::FogLayer, 2> out = fog.sunlit;
  for (std::size_t i = 0; i < 2; ++i)
    out[i].top_irradiance = sunWeight * fog.sunlit[i].top_irradiance + moonWeight * fog.moonIrradiance[i];
  return out;
}

}  // namespace

FogState makeFogState(const atmosphere::AtmosphereModel& model, const FogSpec& haze, const FogSpec& fog,
                      const glm::dvec3& sun, const glm::dvec3& moon, const glm::dvec3& moonlightScale) {
  FogState out;
  const double ground = model.parameters(0).bottom_radius;
  const double albedo = model.config().medium.groundAlbedo;
  const FogSpec specs[2] = {haze, fog};
  for (std::size_t i = 0; i < 2; ++i) {
    weather::validate(specs[i]);
    if (specs[i].visibilityKm == 0.0) continue;
    const double top = ground + specs[i].topM;
    out.sunlit[i] = weather::makeFogLayer(specs[i], ground, albedo, irradianceAt(model, top, sun));
    if (moonlightScale != glm::dvec3(0.0)) out.moonIrradiance[i] = irradianceAt(model, top, moon) * moonlightScale;
  }
  return out;
}

double fogTransmittanceToSpace(const FogState& fog, const atmosphere::AtmosphereModel& model, double heightM,
                               double elevationRad) {
  const double h = glm::length(atmosphere::physicalCamera(model, heightM)) - model.parameters(0).bottom_radius;
  double t = 1.0;
  for (const weather::FogLayer& f : fog.sunlit) t *= shader::fogTransmittance(f, h, std::sin(elevationRad), 1e9);
  return t;
}

std::array<weather::FogLayer, 2> drawnFogLayers(const FogState& fog) { return litBy(fog, 1.0, 1.0); }

std::array<weather::FogLayer, 2> moonlitFogLayers(const FogState& fog) { return litBy(fog, 0.0, 1.0); }

double throughFogLayers(const std::array<weather::FogLayer, 2>& layers, double behindCdM2, double h, double mu,
                        double d) {
  double l = behindCdM2;
  for (const weather::FogLayer& f : layers) l = weather::throughFogLuminance(f, l, h, mu, d);
  return l;
}

}  // namespace skyig::sky
