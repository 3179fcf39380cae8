#pragma once
// A node's configuration (TOML, see config/*.toml): the sky, the default observer for
// `skyig render`, and the display channels. Every value has a default, so an empty file (or
// none) is a valid configuration.
#include "render/channel.h"
#include "render/sky_conditions.h"
#include "render/sky_state.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace skyig::services {

struct NodeConfig {
  std::string nodeName = "ig";
  render::SkyConditions sky;
  render::ObserverState observer;
  std::vector<render::ChannelConfig> channels{render::ChannelConfig{}};
};

// A bad file: what() reads "FILE:LINE: KEY: expected ..., got ..." (the CLI exits with 2).
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

NodeConfig loadNodeConfig(const std::string& path);
NodeConfig parseNodeConfig(const std::string& text, const std::string& sourceName);

}  // namespace skyig::services
