#pragma once
// A cloud layer as a host gives it (CIGI 3.3/4.0 Weather Control layers 1-3, `[[weather.cloud]]`,
// `render --cloud`): its type, its base and thickness above the ground, the coverage, the soft
// edges, the scud and the wind that moves it. Plain data, beside SkyConditions; what a type
// means and which values are good: physics/weather/cloud_layer.h.
#include <array>
#include <cstdint>

namespace skyig::sky {

// CIGI Weather Control's Cloud Type (its 4-bit field: 0 none, 1-10 these, 11-15 "other").
enum class CloudType : std::uint8_t {
  Altocumulus = 1,
  Altostratus,
  Cirrocumulus,
  Cirrostratus,
  Cirrus,
  Cumulonimbus,
  Cumulus,
  Nimbostratus,
  Stratocumulus,
  Stratus,
};

struct CloudLayer {
  bool enabled = false;
  CloudType type = CloudType::Stratus;
  double baseM = 0.0;         // above the ground (the model's ground is mean sea level)
  double thicknessM = 0.0;
  double transitionM = 0.0;   // the base's soft band (CIGI Transition Band)
  double topTransitionM = 0.0;  // the top's (CIGI 4.0 Top Transition Band; 3.3: the same as the base's)
  double coveragePct = 0.0;   // of the sky, 0-100
  int severity = 2;           // CIGI's 0-5: the water content inside (physics/weather/cloud_deck.h); 2 the type's typical
  double visibilityM = 0.0;   // inside; 0: the type's and severity's
  bool scud = false;
  double scudFrequencyPct = 0.0;
  bool topScud = false;       // 4.0
  double topScudFrequencyPct = 0.0;
  double windSpeedMps = 0.0;  // horizontal, the layer moves with it
  double windFromDeg = 0.0;   // the direction it blows from, degrees from true north
  bool operator==(const CloudLayer&) const = default;
};

inline constexpr std::size_t kCloudLayers = 3;  // CIGI's layers 1-3
using CloudLayers = std::array<CloudLayer, kCloudLayers>;

}  // namespace skyig::sky
