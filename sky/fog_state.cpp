#include "sky/fog_state.h"

#include "physics/atmosphere/physical_camera.h"
#include "physics/atmosphere/segment_transmittance.h"
#include "physics/weather/fog_table.h"

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

bool FogState::broken() const {
  return std::any_of(cover.begin(), cover.end(), [](const weather::CloudCover& c) { return c.broken; });
}

weather::FogLayers clouded(const FogState& fog, weather::FogLayers layers) {
  for (std::size_t k = 0; k < kCloudLayers; ++k)
    if (fog.cover[k].broken) layers[weather::kWeatherLayerCount + k].gap = 0.0;
  return layers;
}

weather::FogLayers withoutBrokenDecks(const FogState& fog, weather::FogLayers layers) {
  for (std::size_t k = 0; k < kCloudLayers; ++k)
    if (fog.cover[k].broken) layers[weather::kWeatherLayerCount + k].extinction = 0.0;
  return layers;
}

namespace {

// Deck k's transmittance along `direction` from a point heightM up, offsetM from the eye: where
// its field puts cloud (the share at the ray's crossing of its middle height), its slab's.
double deckTransmittanceAlong(const FogState& fog, std::size_t k, double heightM, const glm::dvec2& offsetM,
                              const glm::dvec3& direction) {
  const weather::CloudCover& c = fog.cover[k];
  weather::FogLayer deck = fog.sunlit[weather::kWeatherLayerCount + k];
  if (deck.extinction <= 0.0) return 1.0;
  deck.gap = 0.0;
  const double through = shader::fogTransmittance(deck, heightM, direction.z, 1e9);
  if (!c.broken) return through;
  const double d = shader::distanceToHeight(deck.planet_radius, heightM, direction.z, c.midHeightM);
  if (d < 0.0) return 1.0;
  const double share = weather::cloudShareAt(c, offsetM + glm::dvec2(direction.x, direction.y) * d);
  return 1.0 - share * (1.0 - through);
}

}  // namespace

double decksTransmittanceAlong(const FogState& fog, double heightM, const glm::dvec2& offsetM,
                               const glm::dvec3& direction) {
  double t = 1.0;
  for (std::size_t k = 0; k < kCloudLayers; ++k) t *= deckTransmittanceAlong(fog, k, heightM, offsetM, direction);
  return t;
}

double cloudFieldFactor(const FogState& fog, double heightM, const glm::dvec3& direction) {
  double factor = 1.0;
  for (std::size_t k = 0; k < kCloudLayers; ++k) {
    const weather::FogLayer& deck = fog.sunlit[weather::kWeatherLayerCount + k];
    if (!fog.cover[k].broken || deck.extinction <= 0.0) continue;
    const double expected = shader::fogTransmittance(deck, heightM, direction.z, 1e9);
    if (expected > 0.0) factor *= deckTransmittanceAlong(fog, k, heightM, glm::dvec2(0.0), direction) / expected;
  }
  return factor;
}

std::array<weather::CloudCover, kCloudLayers> cloudCoversOf(const SkyConditions& conditions, double planetRadiusM,
                                                            double latitudeDeg, double longitudeDeg, double timeS) {
  std::array<weather::CloudCover, kCloudLayers> out{};
  const glm::dvec2 eye = weather::cloudGroundPosition(latitudeDeg, longitudeDeg, planetRadiusM);
  for (std::size_t k = 0; k < kCloudLayers; ++k)
    if (conditions.clouds[k].enabled && conditions.clouds[k].coveragePct > 0.0)
      out[k] = weather::cloudCoverOf(conditions.clouds[k], static_cast<int>(k), eye.x, eye.y, timeS);
  return out;
}

FogState makeFogState(const atmosphere::AtmosphereModel& model, const SkyConditions& conditions,
                      const glm::dvec3& sun, const glm::dvec3& moon, const glm::dvec3& moonlightScale) {
  FogState out;
  const double ground = model.parameters(0).bottom_radius;
  const double albedo = model.config().medium.groundAlbedo;
  const std::array<FogSpec, weather::kWeatherLayerCount> onTheGround{conditions.haze, conditions.fog, conditions.precipitation};
  for (std::size_t i = 0; i < weather::kFogLayerCount; ++i) {
    const bool deck = i >= weather::kWeatherLayerCount;
    const CloudLayer* cloud = deck ? &conditions.clouds[i - weather::kWeatherLayerCount] : nullptr;
    if (cloud && !(cloud->enabled && cloud->coveragePct > 0.0)) continue;
    const FogSpec spec = cloud ? weather::deckSpec(*cloud) : onTheGround[i];
    if (!cloud) weather::validate(spec);
    if (spec.visibilityKm == 0.0) continue;
    const double top = ground + spec.topM;
    const TopLight sunlit = irradianceAt(model, top, sun);
    out.sunlit[i] = cloud ? weather::makeCloudDeck(*cloud, ground, albedo, sunlit.total())
                          : weather::makeFogLayer(spec, ground, albedo, sunlit.total());
    const double lux = shader::rec709Luminance(sunlit.total());
    out.sunShare[i] = lux > 0.0 ? shader::rec709Luminance(sunlit.direct) / lux : 0.0;
    if (moonlightScale != glm::dvec3(0.0)) {
      const TopLight moonlit = irradianceAt(model, top, moon);
      out.moonIrradiance[i] = moonlit.total() * moonlightScale;
      const double moonLux = shader::rec709Luminance(moonlit.total());
      out.moonShare[i] = moonLux > 0.0 ? shader::rec709Luminance(moonlit.direct) / moonLux : 0.0;
    }
  }
  // The weather's layers under a deck are lit by what it lets through (fogShadeBelow).
  for (std::size_t i = 0; i < weather::kWeatherLayerCount; ++i)
    for (std::size_t k = weather::kWeatherLayerCount; k < weather::kFogLayerCount; ++k)
      if (out.sunlit[i].extinction > 0.0 && out.sunlit[k].extinction > 0.0 &&
          out.sunlit[k].bottom_height >= out.sunlit[i].top_height) {
        const double shade = shader::fogShadeBelow(out.sunlit[k]);
        out.sunlit[i].top_irradiance *= shade;
        out.moonIrradiance[i] *= shade;
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

double fogTransmittanceToSpaceAlong(const FogState& fog, const atmosphere::AtmosphereModel& model, double heightM,
                                    const glm::dvec3& direction) {
  const double t = fogTransmittanceToSpace(fog, model, heightM, std::asin(std::clamp(direction.z, -1.0, 1.0)));
  if (!fog.broken()) return t;
  const double h = glm::length(atmosphere::physicalCamera(model, heightM)) - model.parameters(0).bottom_radius;
  return t * cloudFieldFactor(fog, h, direction);
}

weather::FogLayers drawnFogLayers(const FogState& fog) { return litBy(fog, 1.0, 1.0); }

weather::FogLayers moonlitFogLayers(const FogState& fog) { return litBy(fog, 0.0, 1.0); }

weather::AirTransmittance airTransmittanceFrom(const atmosphere::AtmosphereModel& model, double heightM) {
  const double r = model.parameters(0).bottom_radius + heightM;
  return [&model, r](double mu, double d) { return atmosphere::luminanceTransmittance(model, r, mu, d); };
}

double throughFogLayers(const weather::FogLayers& layers, double behindCdM2, double h, double mu,
                        double d, const weather::AirTransmittance& air) {
  const glm::dvec4 f = weather::fogAlong(layers, h, mu, d, air);
  return behindCdM2 * f.a + shader::rec709Luminance(glm::dvec3(f));
}

}  // namespace skyig::sky
