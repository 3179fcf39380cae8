#pragma once
// What a skyig::Sky holds (private to the library): the configuration, the sky worker that
// builds its states as the node's does, and the last state with its light.
#include "skyig/sky.h"

#include "node/host/host_snapshot.h"
#include "node/config/node_config.h"
#include "node/host/node_stats.h"
#include "node/frame/sky_worker.h"
#include "sky/client_light.h"
#include "sky/sky_state.h"

#include <memory>
#include <optional>

namespace skyig {

struct Sky::Impl {
  explicit Impl(const Settings& settings);
  ~Impl();
  // The light of `state`, computed at the first call after an update (a few ms).
  const sky::ClientLight& clientLight() const;

  services::NodeConfig config;  // the worker keeps a reference: Impl never moves (held by pointer)
  services::NodeStats stats;
  std::unique_ptr<atmosphere::AtmosphereUpdater> updater;
  std::unique_ptr<services::SkyWorker> worker;
  services::HostSnapshot host;  // the last update, as a host snapshot
  sky::SkyState state;
  mutable std::optional<sky::ClientLight> light;
};

}  // namespace skyig
