#pragma once
// What a skyig::Sky holds (private to the library): the configuration, the sky worker that
// builds its states as the node's does, and the last state with its light.
#include "skyig/sky.h"

#include "services/host_snapshot.h"
#include "services/node_config.h"
#include "services/node_stats.h"
#include "services/sky_worker.h"
#include "sky/host_light.h"
#include "sky/sky_state.h"

#include <memory>
#include <optional>

namespace skyig {

struct Sky::Impl {
  explicit Impl(const Settings& settings);
  ~Impl();
  // The light of `state`, computed at the first call after an update (a few ms).
  const sky::HostLight& hostLight() const;

  services::NodeConfig config;  // the worker keeps a reference: Impl never moves (held by pointer)
  services::NodeStats stats;
  std::unique_ptr<atmosphere::AtmosphereUpdater> updater;
  std::unique_ptr<services::SkyWorker> worker;
  services::HostSnapshot host;  // the last update, as a host snapshot
  sky::SkyState state;
  mutable std::optional<sky::HostLight> light;
};

}  // namespace skyig
