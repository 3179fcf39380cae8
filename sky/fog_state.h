#pragma once
// The fog layers of a sky state (physics/weather/fog_layer.h) lit by its sun and moon: what the
// sky pass composes over the clear air and the eye's view sphere weighs.
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <memory>
#include <vector>

#include "physics/atmosphere/model.h"
#include "physics/common/sky_conditions.h"
#include "physics/weather/cloud_deck.h"
#include "physics/weather/fog_layer.h"
#include "physics/weather/fog_table.h"

namespace skyig::sky {

// The sky pass's tables of the layers along every view (physics/weather/fog_table.h) for the
// state's eye, made with the state (on the node's worker) instead of on the render thread, where
// each channel's renderer would make its own every frame the eye's height changes: for the eye
// (drawnFogLayers) and for the goggles of class A and B (their haze thinner: goggleFogLayers, the
// eye's own table where there is no haze to thin).
// Where a deck is broken, each table comes twice: with its decks' gaps filled (cloud along every
// view: eye, nvisA, nvisB) and with the broken decks taken out (clear*); the sky pass mixes the two
// per pixel by the decks' field (physics/weather/cloud_cover.glsl). Without a broken deck the
// clear ones are null.
struct FogTables {
  double heightM = -1.0;  // the eye above the ground they are for (physicalCamera's)
  std::shared_ptr<const std::vector<glm::vec4>> eye, nvisA, nvisB;
  std::shared_ptr<const std::vector<glm::vec4>> clearEye, clearNvisA, clearNvisB;
};

// The haze below the tables' visibility, the ground fog, the precipitation, then the host's cloud
// decks (physics/weather/cloud_deck.h); extinction 0: none.
struct FogState {
  weather::FogLayers sunlit{};                                      // lit at the top by the sun and its sky
  std::array<glm::dvec3, weather::kFogLayerCount> moonIrradiance{};  // the moon's share at each top (Rec.709 lux)
  std::array<double, weather::kFogLayerCount> sunShare{};            // of the sunlit top's lux, the direct sun's
  std::array<double, weather::kFogLayerCount> moonShare{};           // of the moonlit top's lux, the direct moon's
  FogTables tables;  // when any(); a state made without them (a test's, the warm-up's) has none
  // Each deck's field for this state's eye and instant (broken: where the sky pass draws it).
  std::array<weather::CloudCover, sky::kCloudLayers> cover{};
  bool any() const;
  bool broken() const;  // a deck with gaps: the sky pass draws its field
};

// The layers of `conditions` (haze, fog, precipitation, the cloud decks) over `model`'s ground,
// lit at their tops by the sun in `sun` (unit, the model's frame: up is +z at the camera) and the
// moon in `moon` scaled by moonlightScale (linear Rec.709). Throws std::invalid_argument for a bad
// layer. The decks' fields (cover) are the caller's: they need the eye's place and time
// (cloudCoversOf).
FogState makeFogState(const atmosphere::AtmosphereModel& model, const SkyConditions& conditions,
                      const glm::dvec3& sun, const glm::dvec3& moon, const glm::dvec3& moonlightScale);

// The layers' transmittance from an observer heightM above the ground (physicalCamera's height)
// to space at elevation e (radians): what the stars, the moon and the night's light keep.
double fogTransmittanceToSpace(const FogState& fog, const atmosphere::AtmosphereModel& model, double heightM,
                               double elevationRad);

// The decks' fields for an eye at latitudeDeg, longitudeDeg at timeS seconds of the host's clock
// (seconds since J2000, UTC).
std::array<weather::CloudCover, sky::kCloudLayers> cloudCoversOf(const SkyConditions& conditions, double planetRadiusM,
                                                                 double latitudeDeg, double longitudeDeg, double timeS);

// The layers' transmittance to space along an ENU unit `direction` from an observer heightM above
// the ground: fogTransmittanceToSpace with a broken deck's cloud or gap where the view crosses it
// (cloudFieldFactor): the sun's and the moon's direct light, the discs' glare.
double fogTransmittanceToSpaceAlong(const FogState& fog, const atmosphere::AtmosphereModel& model, double heightM,
                                    const glm::dvec3& direction);

// The cloud decks' transmittance along an ENU unit `direction` from a point heightM above the
// ground, offsetM metres (east, north) from the state's eye: a whole deck's along the ray, a
// broken one's where its field has cloud where the ray crosses its middle height (1 in a gap).
// The sun's light on a terrain point under the clouds (skyig::Sky::sunThroughClouds).
double decksTransmittanceAlong(const FogState& fog, double heightM, const glm::dvec2& offsetM,
                               const glm::dvec3& direction);

// What reaches the eye heightM above the ground from beyond the broken decks along an ENU unit
// `direction` (a star, a planet, the moon), over what their gaps let through on average (the
// state's extinction profile, which weighs them by their coverage): 0 behind a cloud, over 1 in a
// gap, as the sky pass's field has them there.
double cloudFieldFactor(const FogState& fog, double heightM, const glm::dvec3& direction);

// The layers with the broken decks' gaps filled (every view meets cloud) or with them taken out
// (no view does): the two tables the sky pass mixes by the field.
weather::FogLayers clouded(const FogState& fog, weather::FogLayers layers);
weather::FogLayers withoutBrokenDecks(const FogState& fog, weather::FogLayers layers);

// The layers as the sky pass draws them: each lit by the sun and the moon together.
weather::FogLayers drawnFogLayers(const FogState& fog);
// The layers lit by the moon alone (its share of each top's irradiance): the eye's view sphere
// keeps the sunlit and the moonlit light apart.
weather::FogLayers moonlitFogLayers(const FogState& fog);

// What the eye h metres above the ground sees through every layer of `layers` along (mu, d) where
// the clear air shows `behindCdM2` (luminances; the fog is grey), the decks through `air`.
double throughFogLayers(const weather::FogLayers& layers, double behindCdM2, double h, double mu,
                        double d, const weather::AirTransmittance& air = nullptr);

// The clear air's transmittance from an eye heightM above `model`'s ground along a view (the
// composites' `air`: physics/atmosphere/segment_transmittance.h).
weather::AirTransmittance airTransmittanceFrom(const atmosphere::AtmosphereModel& model, double heightM);

}  // namespace skyig::sky
