#pragma once
// Loads the physical atmosphere's tables when the configuration asks for the physical sky:
// from the disk cache when a file matches every parameter, else precomputed (and cached).
#include "services/node_config.h"

namespace skyig::services {

// Sets config.sky.atmosphere when config.sky.model is physical; prints to stderr when it has
// to precompute (seconds for the small tables on a CPU).
void loadAtmosphereIfNeeded(NodeConfig& config);

}  // namespace skyig::services
