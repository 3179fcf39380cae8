#pragma once
// What a configuration says of the physical sky's tables: their size, the medium, the
// visibility they are first built for, where they are cached and how much, and the visibility
// steps kept for blending. Read from [sky] and [atmosphere] (node/config/node_config.h).
#include "physics/atmosphere/medium.h"
#include "tables/visibility_blend.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace skyig::services {

// Tables of the physical sky (sky.model = "physical"): their size and cache ([sky]) and the
// medium they are computed for ([atmosphere]; Bruneton's 2017 Earth by default).
struct AtmosphereSettings {
  // "medium" (the default: within 3% of Bruneton's tables up to 5 km, ~28 s once on llvmpipe),
  // "small" (2 s; for tests, coarse at sunset) or "default" (Bruneton's sizes, for a GPU).
  std::string tables = "medium";
  atmosphere::Medium medium;  // the ground albedo comes from sky.ground_albedo
  int scatteringOrders = 4;
  // The visibility (km, Koschmieder) the tables are computed for until the host says otherwise
  // ([atmosphere] visibility_km, `render --visibility`); unset: the medium's own aerosols.
  std::optional<double> visibilityKm;
  std::string cacheDir;          // "" = $CACHE_DIRECTORY (systemd), else $XDG_CACHE_HOME/skyig or ~/.cache/skyig
  // The cache's size bound (least recently used tables evicted; 0: none) and at most one
  // precompute for the host's conditions per buildIntervalS (0: no limit). A distinct
  // visibility must also be held for the debounce time (node/host/host_atmosphere.h).
  std::uint64_t cacheMaxBytes = 512ull << 20;
  double buildIntervalS = 60.0;
  // Visibilities (km) whose tables `serve` keeps besides the configuration's own ([sky]
  // atmosphere_visibility_steps; built in the background on a first start, or by `skyig
  // precompute`): a host's visibility between two is shown at once as their blend while its
  // exact tables are built (tables/visibility_blend.h). Empty: no blending.
  std::vector<double> visibilityStepsKm = atmosphere::defaultVisibilityStepsKm();
};

}  // namespace skyig::services
