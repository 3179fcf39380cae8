#pragma once
// What the sky depends on besides the sun: the model and the state of the air and ground.
#include "physics/common/cloud_layer.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace skyig::atmosphere {
class AtmosphereModel;
}
namespace skyig::sky::night {
class StarCatalogue;
}

namespace skyig::sky {

enum class SkyModel { Preetham, Cie, Physical };

// Koschmieder's relation (Koschmieder 1924; WMO No. 8): an object is just visible at the
// distance where its contrast falls to 2%, V = ln(50) / beta_ext = 3.912 / beta_ext. Here with
// FogSpec, whose visibilities it turns into extinctions; physics/atmosphere/conditions.h names it too.
inline constexpr double kKoschmiederConstant = 3.912;

// The asymmetry factor of fog and cloud droplets in the visible (Hansen & Travis 1974: 0.85).
inline constexpr double kDropletAsymmetry = 0.85;

// A layer of fog, mist, precipitation or dust (physics/weather/fog_layer.h): from bottomM to topM
// above the ground, visibilityKm inside it; a visibility of 0 is no layer. Its particles' optics
// (physics/weather/precipitation.h) default to fog's water droplets.
struct FogSpec {
  double bottomM = 0.0;
  double topM = 0.0;
  double visibilityKm = 0.0;
  double asymmetry = kDropletAsymmetry;           // g of the phase function, [0, 1)
  std::array<double, 3> albedo{1.0, 1.0, 1.0};   // single-scattering albedo per Rec.709 channel
  // CIGI Weather Control's transition band: over this height above the top (and below a bottom
  // above the ground) the extinction falls linearly to none, so the layer's edge is soft.
  double transitionM = 0.0;
  // A band of its own below a raised bottom (a cloud deck's base: CIGI 4.0 gives the top's and
  // the base's apart); none: transitionM.
  std::optional<double> bottomTransitionM = std::nullopt;
  bool operator==(const FogSpec&) const = default;
};

std::string_view toString(SkyModel model);
// "preetham", "cie" or "physical"; false for anything else.
bool parseSkyModel(std::string_view text, SkyModel& model);

struct SkyConditions {
  SkyModel model = SkyModel::Preetham;
  int cieType = 12;             // 1..15, for SkyModel::Cie
  double turbidity = 2.5;       // Preetham's T, [1.7, 10]
  double groundAlbedo = 0.2;    // Lambertian, [0, 1]
  double sunDistanceAu = 1.0;   // scales the solar illuminance by 1/d^2
  // SkyModel::Physical: the precomputed atmosphere (Bruneton & Neyret 2008), loaded by the
  // caller (node/config/node_tables.h) and shared, immutable, by every state.
  std::shared_ptr<const atmosphere::AtmosphereModel> atmosphere;
  // The bright stars (physics/stars/star_catalogue.h), loaded once by the caller; without it
  // only the planets are drawn.
  std::shared_ptr<const night::StarCatalogue> starCatalogue;
  // CIGI Celestial Sphere Control: star field intensity / 100, 0 when the field is disabled.
  double starFieldIntensity = 1.0;
  // SkyModel::Physical: the air below the tables' visibility (physics/weather/fog_layer.h,
  // hazeBelowTables), a ground fog (CIGI Weather Control layer 0, [weather], render --fog-*) and
  // the precipitation or dust (CIGI Weather Control layers 4-9, physics/weather/precipitation.h).
  FogSpec haze;
  FogSpec fog;
  FogSpec precipitation;
  // The host's cloud layers (CIGI Weather Control layers 1-3, [[weather.cloud]], render --cloud):
  // drawn as decks (physics/weather/cloud_deck.h) and recorded (state dump, EXR header).
  CloudLayers clouds{};
};

}  // namespace skyig::sky
