#pragma once
// Precipitation and dust as layers of the fog model (fog_layer.glsl): CIGI Weather Control's
// layers 4 to 9 (rain, snow, sleet, hail, sand, dust), each a slab of particles with the
// visibility and the optics of its kind. Rain, snow, sleet and hail are grey (water and ice
// absorb nothing over a drop in the visible); sand and dust absorb blue more than red and tint
// the air brown-yellow. A host that gives no visibility gets the one its severity (0-5) names.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "physics/common/sky_conditions.h"

namespace skyig::weather {

// In CIGI's layer order: layer id = 4 + the enumerator.
enum class Precipitation : std::uint8_t { rain, snow, sleet, hail, sand, dust };
inline constexpr std::uint8_t kFirstPrecipitationLayerId = 4;
inline constexpr std::size_t kPrecipitationKinds = 6;

std::string_view toString(Precipitation kind);
// "rain", "snow", "sleet", "hail", "sand" or "dust"; nullopt for anything else.
std::optional<Precipitation> parsePrecipitation(std::string_view text);
// The kind of CIGI Weather Control layer `layerId`, nullopt outside 4-9.
std::optional<Precipitation> precipitationOfLayer(std::uint8_t layerId);

// The visibility (km) inside a layer of `kind` at CIGI severity 0 (least) to 5 (most):
// rain from its rate (Marshall & Palmer 1948's drops), snow and sleet from the visibilities that
// name their intensity, sand and dust from WMO's dust haze, dust storm and severe dust storm.
double visibilityForSeverityKm(Precipitation kind, int severity);

// The rain rate (mm/h) CIGI severity 0-5 stands for: light 1 to violent 50 (WMO's classes).
double rainRateMmPerH(int severity);
// Rain of rate R (mm/h) whose drops follow Marshall & Palmer (1948), N(D) = N0 exp(-Lambda D),
// N0 = 8000 m^-3 mm^-1, Lambda = 4.1 R^-0.21 mm^-1, each drop removing twice its cross-section
// (the extinction paradox, drops far larger than the wavelength): sigma = 2 int pi D^2 / 4 N dD =
// pi N0 / Lambda^3 (D in mm: x 1e-6 m^2/mm^2). Visibility 3.912 / sigma (Koschmieder), km.
double rainVisibilityKm(double rateMmPerH);

// A layer of `kind` from bottomM to topM above the ground with `visibilityKm` inside (0: from
// `severity`), covering `coverage` (0-1) of the sky: its extinction the area's mean, so half a
// cover doubles the visibility. A coverage of 0 gives no layer.
sky::FogSpec precipitationLayer(Precipitation kind, double bottomM, double topM, double visibilityKm,
                                int severity, double coverage);

// Precipitation as a configuration or a command line states it ([weather], render
// --precipitation): of `kind` (none: no layer) from the ground to topM.
struct PrecipitationSettings {
  std::optional<Precipitation> kind;
  int severity = 2;            // CIGI's 0 (least) to 5 (most)
  double visibilityKm = 0.0;   // inside; 0: the severity's
  double topM = 1500.0;        // above the ground
  double coveragePct = 100.0;
};
// The layer of `settings` (precipitationLayer); throws std::invalid_argument for a bad value.
sky::FogSpec precipitationLayer(const PrecipitationSettings& settings);

// Several layers at once in the one slot the sky draws: their extinctions added, the optics
// weighted by each one's scattering, spanning from the lowest bottom to the highest top (its
// visibility so that the layers' summed vertical optical depth is kept). Layers of visibility 0
// are skipped; none left gives no layer.
sky::FogSpec combinedLayers(std::span<const sky::FogSpec> layers);

}  // namespace skyig::weather
