#include "node/config/sky_data.h"

#include "ephemeris/data_files.h"
#include "ephemeris/time_scales.h"
#include "node/config/node_tables.h"

#include <exception>
#include <stdexcept>

namespace skyig::services {

std::string starCataloguePath(const std::string& configured) {
  return configured.empty() ? ephemeris::dataFilePath("bsc5.csv") : configured;
}

std::shared_ptr<const sky::night::StarCatalogue> loadConfiguredStarCatalogue(const std::string& configured,
                                                                              const ephemeris::UtcTime& epoch) {
  // The catalogue's proper motion needs the epoch on the ephemeris' time scales: a year
  // outside their range is the observer's time at fault, not the catalogue.
  try {
    (void)ephemeris::timeScales(epoch);
  } catch (const std::invalid_argument& e) {
    throw ConfigError("the observer's time (observer.utc or --utc): " + std::string(e.what()));
  }
  if (configured == "none") return nullptr;
  try {
    const std::string path = configured.empty() ? ephemeris::requireDataFile("bsc5.csv") : configured;
    return sky::night::loadStarCatalogue(path, epoch);
  } catch (const std::exception& e) {
    throw ConfigError("sky.star_catalogue: " + std::string(e.what()));
  }
}

void loadSkyData(NodeConfig& config, const std::atomic<bool>* stop) {
  // The catalogue first: a missing file stops the command at once, not after a precompute.
  // Proper motion at the configured observer's epoch: a host's clock years away moves a bright
  // star by under an arcminute.
  if (!config.sky.starCatalogue)
    config.sky.starCatalogue = loadConfiguredStarCatalogue(config.starCataloguePath, config.observer.utc);
  loadAtmosphereIfNeeded(config, stop);
}

}  // namespace skyig::services
