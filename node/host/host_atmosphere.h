#pragma once
// The host's visibility and humidity (CIGI Atmosphere Control, or global Weather Control)
// turned into requests for a new physical atmosphere (tables/updater.h): debounced,
// so a host ramping the fog asks for one model once the value settles, and validated, so a
// value the model cannot represent is counted and ignored and the last good atmosphere stays.
#include "physics/atmosphere/conditions.h"
#include "physics/atmosphere/model.h"
#include "node/host/host_state.h"

#include <optional>

namespace skyig::services {

// How long a host's value must hold before it is asked for: long enough that a slider dragged
// through the values (a new one every host frame, 17-33 ms at 30-60 Hz) asks once, at its end,
// rather than for every step of the drag; short, because the answer is a blend of cached
// visibility steps made in ~0.3 s (tables/visibility_blend.h), not minutes of precompute.
inline constexpr double kHostAtmosphereDebounceS = 0.1;

class HostAtmosphere {
 public:
  // The host's values before it says anything are HostState's defaults; until they change
  // the node keeps the configuration's atmosphere.
  HostAtmosphere(const atmosphere::Medium& base, double groundAlbedo, double debounceS = kHostAtmosphereDebounceS);

  // The host's values at `now`. Returns the conditions to ask for once the values differ from
  // the last ones asked for and have not changed for the debounce time. Throws
  // std::invalid_argument naming a bad value (non-finite, visibility not in (0, clean-air
  // limit of the medium), humidity outside [0, 100] %), once per bad value.
  std::optional<atmosphere::Conditions> observe(double visibilityM, double humidityPct, Clock::time_point now);

 private:
  struct Values {
    double visibilityM;
    double humidityPct;
    bool operator==(const Values&) const = default;
  };
  atmosphere::Medium base_;
  double groundAlbedo_;
  Clock::duration debounce_;
  Values requested_;
  Values candidate_;
  Clock::time_point candidateSince_{};
  std::optional<Values> rejected_;
};

}  // namespace skyig::services
