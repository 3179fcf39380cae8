#include "sky/fog_state.h"

#include "physics/atmosphere/physical_camera.h"

#include <algorithm>
#include <cmath>

namespace skyig::sky {

namespace {

// Sun (or moon) and sky on a horizontal surface at radius r above the model's origin, Rec.709 lux:
// the direct light and the sky's.
struct TopLight {
  glm::dvec3 direct, sky;
  glm::dvec3 total() const { return direct + sky; }
};
TopLight irradianceAt(const atmosphere::AtmosphereModel& model, double r, const glm::dvec3& light) {
  const glm::dvec3 point(0.0, 0.0, r), up(0.0, 0.0, 1.0);
  return {model.converter().toRec709(model.sunIrradiance(point, up, light)),
          model.converter().toRec709(model.skyIrradiance(point, up, light))};
}

// The layers lit at their tops by sun * sunWeight + moon * moonWeight.
weather::FogLayers litBy(const FogState& fog, double sunWeight, double moonWeight) {
  weather::FogLayers out = fog.sunlit;
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i].top_irradiance = sunWeight * fog.sunlit[i].top_irradiance + moonWeight * fog.moonIrradiance[i];
  return out;
}

}  // namespace

bool FogState::any() const {
  return std::any_of(sunlit.begin(), sunlit.end(), [](const weather::FogLayer& f) { return f.extinction > 0.0; });
}

FogState makeFogState(const atmosphere::AtmosphereModel& model, const SkyConditions& conditions,
                      const glm::dvec3& sun, const glm::dvec3& moon, const glm::dvec3& moonlightScale) {
  FogState out;
  const double ground = model.parameters(0).bottom_radius;
  const double albedo = model.config().medium.groundAlbedo;
  const std::array<FogSpec, weather::kFogLayerCount> specs{conditions.haze, conditions.fog, conditions.precipitation};
  for (std::size_t i = 0; i < specs.size(); ++i) {
    weather::validate(specs[i]);
    if (specs[i].visibilityKm == 0.0) continue;
    const double top = ground + specs[i].topM;
    const TopLight sunlit = irradianceAt(model, top, sun);
    out.sunlit[i] = weather::makeFogLayer(specs[i], ground, albedo, sunlit.total());
    const double lux = shader::rec709Luminance(sunlit.total());
    out.sunShare[i] = lux > 0.0 ? shader::rec709Luminance(sunlit.direct) / lux : 0.0;
    if (moonlightScale != glm::dvec3(0.0)) {
      const TopLight moonlit = irradianceAt(model, top, moon);
      out.moonIrradiance[i] = moonlit.total() * moonlightScale;
      const double moonLux = shader::rec709Luminance(moonlit.total());
      out.moonShare[i] = moonLux > 0.0 ? shader::rec709Luminance(moonlit.direct) / moonLux : 0.0;
    }
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

weather::FogLayers drawnFogLayers(const FogState& fog) { return litBy(fog, 1.0, 1.0); }

weather::FogLayers moonlitFogLayers(const FogState& fog) { return litBy(fog, 0.0, 1.0); }

double throughFogLayers(const weather::FogLayers& layers, double behindCdM2, double h, double mu,
                        double d) {
  double l = behindCdM2;
  for (const weather::FogLayer& f : layers) l = weather::throughFogLuminance(f, l, h, mu, d);
  return l;
}

}  // namespace skyig::sky
