#pragma once
// Options shared by the commands that set up a sky: configuration file, place, attitude,
// time, sky model and sun override. Values left unset keep the configuration's.
#include "node/config/node_config.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace skyig::services {

struct SkyOptions {
  std::string configPath;
  std::optional<double> lat, lon, alt, yaw, pitch, roll, turbidity, groundAlbedo, visibilityKm;
  std::optional<double> fogVisibilityKm, fogBottomM, fogTopM, fogTransitionM;  // a ground fog ([weather])
  // Precipitation or dust ([weather] precipitation_*): a kind or "none", and its figures.
  std::optional<std::string> precipitation;
  std::optional<int> precipitationSeverity;
  std::optional<double> precipitationVisibilityKm, precipitationTopM, precipitationCoveragePct;
  // Cloud layer 1 ([[weather.cloud]]): "TYPE:BASE:THICKNESS[:COVERAGE[:WIND:FROM]]".
  std::optional<std::string> cloud;
  std::optional<std::string> aerosol;  // --aerosol: an OPAC type or bruneton2017 (physics/atmosphere/aerosol_type.h)
  std::optional<double> sunAzimuth, sunElevation;
  std::optional<std::string> utc, skyModel;
  std::optional<int> cieType;

  void add(CLI::App& command);
  // The configuration with the options applied; throws ConfigError on a bad value.
  NodeConfig resolve() const;
  std::optional<sky::SunOverride> sunOverride() const;
};

// "WIDTHxHEIGHT" with each in sky::kMinChannelSide..kMaxChannelSide (16..8192, --size);
// throws ConfigError naming the flag.
void parseSize(const std::string& text, int& width, int& height);

}  // namespace skyig::services
