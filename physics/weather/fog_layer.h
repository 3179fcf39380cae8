#pragma once
// Fog and mist as layers over the clear-air sky (fog_layer.glsl: the two-stream slab). The
// precomputed tables hold the clear air and haze down to kTablesVisibilityKm; a lower visibility
// is the tables at that visibility and the rest of the extinction as a layer from the ground to
// the aerosols' scale height, which has the same vertical optical depth as the tables' exponential
// profile would. Below about 10 km the successive orders of the tables no longer converge in four
// orders (docs/atmosphere.md, "Multiple scattering in haze"), and every lower visibility would
// cost a table build; the layer is exact for its own multiple scattering (within the two-stream
// approximation) and free to change every frame.
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>

#include "physics/common/sky_conditions.h"
#include "physics/weather/weather_physics.h"

namespace skyig::weather {

using FogLayer = shader::weather_types::FogLayer;
using FogEye = shader::weather_types::FogEye;

// The lowest visibility the tables are built for; below it the layer takes the rest.
inline constexpr double kTablesVisibilityKm = 10.0;
// The layers over the clear air: the haze below the tables' visibility, the ground fog, the
// precipitation (the weather's, kWeatherLayerCount), then the host's cloud decks
// (physics/weather/cloud_deck.h; sky/fog_state.h).
inline constexpr std::size_t kWeatherLayerCount = 3;
inline constexpr std::size_t kFogLayerCount = kWeatherLayerCount + sky::kCloudLayers;
using FogLayers = std::array<FogLayer, kFogLayerCount>;

// The visibility the tables are built for: the host's, or kTablesVisibilityKm if it is lower.
double tablesVisibilityKm(double visibilityKm);

// The layer holding what a visibility below the tables' leaves: from the ground to scaleHeightM,
// with the extinction 3.912 / V - 3.912 / kTablesVisibilityKm (Koschmieder at the ground: the
// tables' aerosols and the layer together), given as the visibility inside; no layer (visibility
// 0) at or above kTablesVisibilityKm.
sky::FogSpec hazeBelowTables(double visibilityKm, double scaleHeightM);

// Throws std::invalid_argument naming a bad value (negative or non-finite heights, a top below
// the bottom, a negative visibility, an asymmetry outside [0, 1), an albedo outside (0, 1]).
void validate(const sky::FogSpec& spec);

// The layer of `spec` over a planet of radius planetRadiusM whose ground has `groundAlbedo`, lit
// at its top by topIrradiance (linear Rec.709 lux on a horizontal surface from above). A spec
// without a layer gives extinction 0.
FogLayer makeFogLayer(const sky::FogSpec& spec, double planetRadiusM, double groundAlbedo,
                      const glm::dvec3& topIrradiance);

// throughFog for luminances (the extinction is grey, so what lies behind is dimmed alike in every
// channel; the layer's own light, tinted where it absorbs, is added as its luminance): what the
// eye h metres above the ground sees of `behindCdM2` along (mu, d).
double throughFogLuminance(const FogLayer& fog, double behindCdM2, double h, double mu, double d);

}  // namespace skyig::weather
