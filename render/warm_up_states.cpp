#include "render/warm_up_states.h"

#include "physics/common/units.h"
#include "physics/weather/cloud_deck.h"
#include "physics/weather/fog_layer.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace skyig::render {

namespace {

// What decides a frame's programs besides its weather and its view: the layers drawn
// (sky/shown_layers.h) and the glare veil's sources.
auto programKey(const skyig::sky::SkyState& s) {
  const skyig::sky::ShownLayers& l = s.shown;
  const auto lit = std::count_if(s.glare.begin(), s.glare.end(),
                                 [](const skyig::sky::eye::GlareSource& g) { return g.rec709Lux != glm::dvec3(0.0); });
  return std::tuple{l.sunlitSky, l.moonlitSky, l.nightLight, l.mesopic, l.pointSources, lit};
}

// The same light under a ground fog 200 m deep of 400 m visibility: the sky pass's weather
// variant and the fog's share in every pass that reads it.
skyig::sky::SkyState underFog(skyig::sky::SkyState s) {
  const double ground = s.conditions.atmosphere->parameters(0).bottom_radius;
  s.fog.sunlit[1] = weather::makeFogLayer({0.0, 200.0, 0.4}, ground, 0.2, glm::dvec3(1.0));
  s.fog.tables = {};  // the state's own tables are for its own layers: the pass makes this one's
  return s;
}

// The same light under a broken stratocumulus deck at 1.5 km over that fog: the sky pass's cloud
// variants (its field and its decks' single-scattered light).
skyig::sky::SkyState underCloud(skyig::sky::SkyState s) {
  s = underFog(std::move(s));
  const double ground = s.conditions.atmosphere->parameters(0).bottom_radius;
  skyig::sky::CloudLayer deck;
  deck.enabled = true;
  deck.type = skyig::sky::CloudType::Stratocumulus;
  deck.baseM = 1500.0;
  deck.thicknessM = 500.0;
  deck.coveragePct = 50.0;
  s.fog.sunlit[weather::kWeatherLayerCount] = weather::makeCloudDeck(deck, ground, 0.2, glm::dvec3(1.0));
  s.fog.cover[0] = weather::cloudCoverOf(deck, 0, 0.0, 0.0, 0.0);
  return s;
}

}  // namespace

std::vector<skyig::sky::SkyState> warmUpStates(const skyig::sky::SkyState& first,
                                               const std::vector<skyig::sky::DisplayParams>& displays) {
  std::vector<skyig::sky::SkyState> states{first};
  if (first.ephemeris) {  // an overridden sun has no day to walk through
    skyig::sky::SkyStateCaches caches;
    for (int halfHour = 0; halfHour < 48; ++halfHour) {
      skyig::sky::ObserverState o = first.observer;
      const double solarHour = 0.5 * halfHour;
      o.utc.secondsOfDay = std::fmod(3600.0 * (solarHour - o.longitudeDeg / 15.0) + 2.0 * 86400.0, 86400.0);
      skyig::sky::SkyState s = skyig::sky::buildSkyState(o, first.conditions, std::nullopt, &caches);
      skyig::sky::mapForDisplays(s, displays);
      bool seen = false;
      for (const skyig::sky::SkyState& earlier : states) seen = seen || programKey(earlier) == programKey(s);
      if (!seen) states.push_back(std::move(s));
    }
  }
  const bool physical = first.conditions.model == skyig::sky::SkyModel::Physical && first.conditions.atmosphere;
  if (physical) {
    const std::size_t clear = states.size();
    for (std::size_t i = 0; i < clear; ++i) states.push_back(underFog(states[i]));
    states.push_back(underCloud(states[0]));  // the first light's only: each costs its programs' compiles
    // And a night's under the deck, for the night's light through its field (a goggle's night
    // pass), where the first light is the day's.
    auto night = [](const skyig::sky::SkyState& s) { return s.ephemeris && s.sunAltitude < 0.0; };
    for (std::size_t i = 1; i < clear && !night(states[0]); ++i)
      if (night(states[i])) {
        states.push_back(underCloud(states[i]));
        break;
      }
  }
  return states;
}

std::vector<skyig::sky::Attitude> warmUpAttitudes(const skyig::sky::SkyState& state, const skyig::sky::Attitude& own) {
  std::vector<skyig::sky::Attitude> attitudes{own};
  for (const skyig::sky::eye::GlareSource& g : state.glare) {
    if (g.rec709Lux == glm::dvec3(0.0)) continue;
    const glm::dvec3 d = glm::normalize(g.direction);  // east, north, up
    attitudes.push_back({std::atan2(d.x, d.y) / kDeg, std::asin(std::clamp(d.z, -1.0, 1.0)) / kDeg, 0.0});
  }
  return attitudes;
}

}  // namespace skyig::render
