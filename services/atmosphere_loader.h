#pragma once
// Loads the physical atmosphere's tables when the configuration asks for the physical sky:
// from the disk cache when a file matches every parameter, else precomputed (and cached).
#include "render/atmosphere/conditions.h"
#include "render/atmosphere/model.h"
#include "services/node_config.h"

#include <memory>

namespace skyig::services {

// The model of `settings` under `conditions`, from the cache directory (settings.cacheDir, else
// $XDG_CACHE_HOME/skyig or ~/.cache/skyig) or precomputed and cached there; says on stderr when
// it has to precompute. `orders`: scattering orders (4 by default).
std::shared_ptr<const atmosphere::AtmosphereModel> loadAtmosphere(const AtmosphereSettings& settings,
                                                                  const atmosphere::Conditions& conditions,
                                                                  int orders = 4);

// Sets config.sky.atmosphere when config.sky.model is physical; prints to stderr when it has
// to precompute (seconds for the small tables on a CPU).
void loadAtmosphereIfNeeded(NodeConfig& config);

}  // namespace skyig::services
