#pragma once
// What the sky reads from disk before the first frame, for every command that draws or probes
// it: the physical atmosphere's tables (tables/loader.h) and the star catalogue.
#include "physics/stars/star_catalogue.h"
#include "node/config/node_config.h"

#include <atomic>
#include <memory>
#include <string>

namespace skyig::services {

// The catalogue file `configured` names: itself, or for "" the bundled BSC5, bsc5.csv in
// skyig's data directory ($SKYIG_DATA_DIR, else <executable's directory>/../share/skyig;
// ephemeris/data_files.h).
std::string starCataloguePath(const std::string& configured);

// The catalogue of `configured` prepared for `epoch` (proper motion), or null for "none".
// Throws ConfigError naming the file when it cannot be read or parsed (for the bundled one, also
// how its directory was chosen).
std::shared_ptr<const sky::night::StarCatalogue> loadConfiguredStarCatalogue(const std::string& configured,
                                                                              const ephemeris::UtcTime& epoch);

// Sets config.sky.atmosphere (physical model) and config.sky.starCatalogue (at the observer's
// epoch) where they are not set yet. Once `stop` is set, a precompute of the tables ends within
// a slice with atmosphere::Cancelled (a command signalled while it starts).
void loadSkyData(NodeConfig& config, const std::atomic<bool>* stop = nullptr);

}  // namespace skyig::services
