#include "services/sky_data.h"

#include "services/atmosphere_loader.h"

#include <cstdlib>
#include <exception>

#ifndef SKYIG_DEFAULT_STAR_CATALOGUE
#error "SKYIG_DEFAULT_STAR_CATALOGUE must name ephemeris/data/bsc5.csv (services/CMakeLists.txt)"
#endif

namespace skyig::services {

std::string starCataloguePath(const std::string& configured) {
  if (!configured.empty()) return configured;
  const char* dir = std::getenv("SKYIG_DATA_DIR");
  return dir && *dir ? std::string(dir) + "/bsc5.csv" : std::string(SKYIG_DEFAULT_STAR_CATALOGUE);
}

std::shared_ptr<const sky::night::StarCatalogue> loadConfiguredStarCatalogue(const std::string& configured,
                                                                              const ephemeris::UtcTime& epoch) {
  if (configured == "none") return nullptr;
  const std::string path = starCataloguePath(configured);
  try {
    return sky::night::loadStarCatalogue(path, epoch);
  } catch (const std::exception& e) {
    throw ConfigError("sky.star_catalogue: " + std::string(e.what()));
  }
}

void loadSkyData(NodeConfig& config) {
  loadAtmosphereIfNeeded(config);
  // Proper motion at the configured observer's epoch: a host's clock years away moves a bright
  // star by under an arcminute.
  if (!config.sky.starCatalogue)
    config.sky.starCatalogue = loadConfiguredStarCatalogue(config.starCataloguePath, config.observer.utc);
}

}  // namespace skyig::services
