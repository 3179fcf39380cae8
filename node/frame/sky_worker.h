#pragma once
// The sky worker: the host's state -> what a frame shows. The one piece of code `skyig serve`
// (node/node.cpp, on its worker and render threads) and `skyig replay` (node/record/replay.cpp,
// on the recording's clock) both run, so a replay re-renders the flight the node showed: the
// host's ownship, clock, air (pressure and temperature refract the sun, moon and stars), star
// field intensity, view overrides and visibility/humidity (a new physical atmosphere).
//
// It owns what consecutive states share: the ephemeris and extinction caches and the follower
// of the host's atmosphere. One SkyWorker per thread that builds states.
#include "tables/updater.h"
#include "physics/eye/adaptation.h"
#include "sky/sky_state.h"
#include "node/host/host_atmosphere.h"
#include "node/config/node_tables.h"
#include "node/host/host_snapshot.h"
#include "node/config/node_config.h"
#include "node/host/node_stats.h"

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

namespace skyig::services {

// What a frame is drawn with besides the SkyState: the ownship's attitude at the frame's own
// instant (the state was built at the worker's) and the channels as the host last set them.
struct FramePose {
  sky::Attitude attitude;
  std::vector<sky::ChannelConfig> channels;
};

class SkyWorker {
 public:
  // `config.sky` is the configured sky; with the physical model, `updater` rebuilds it for the
  // host's visibility and humidity (null: the configured atmosphere stays). `stats` counts what
  // the host sent that the sky cannot use.
  SkyWorker(const NodeConfig& config, atmosphere::AtmosphereUpdater* updater, NodeStats& stats);

  // Follows the host's visibility and humidity at `now` (debounced, validated, sent to the
  // updater as a request) and takes the updater's newest model. Returns true when the model
  // changed since the last call. With `wait`, a request is waited for (replay: the tables for
  // the host's visibility are in the next state, whatever the machine's speed).
  bool followAtmosphere(const HostSnapshot* host, Clock::time_point now, bool wait = false);

  // The state due at local instant `now`, if one is: for a host message not seen before, the
  // state at the message's own instant, with the eye's adaptation stepped on the host's clock
  // at that message and at each earlier one this worker skipped (HostSnapshot::earlier), so two
  // nodes and a replay of one stream adapt alike however loaded each machine is; otherwise, when the host has been
  // silent for `refresh` or `force` is set (new tables), the state at `now` with the eye as it
  // is. Throws std::invalid_argument for a host state the sky cannot use: the caller counts it
  // and keeps its last state.
  std::optional<sky::SkyState> step(const HostSnapshot* host, Clock::time_point now, bool force = false,
                                    Clock::duration refresh = std::chrono::milliseconds(100));

  // Synchronous mode: every state is at a host message's instant, never at the local clock's.
  // Once the host has spoken, a refresh without a new message (new tables) rebuilds the last
  // message's instant, and a silent host gets no new state (the dome holds its last frame), so
  // whatever a node shows for host frame N depends on the host's messages alone.
  void setHostInstantsOnly(bool on) { hostInstantsOnly_ = on; }

  // The state at local instant `t` with the eye as it is now (no step in time).
  sky::SkyState build(const HostSnapshot* host, Clock::time_point t) {
    sky::SkyState s = scene(host, t);
    adaptAndMap(s);
    return s;
  }

  // The observer at `t`: the host's ownship predicted to `t`, its clock and its air; the
  // configuration's observer for what the host has not said.
  sky::ObserverState observerAt(const HostSnapshot* host, Clock::time_point t) const;
  // The frame drawn at `t` (the render thread's step): `channels` with the host's view overrides.
  FramePose poseAt(const HostSnapshot* host, Clock::time_point t, const std::vector<sky::ChannelConfig>& channels) const;

 private:
  // The sky at `t` without the eye: what the eye adapts to.
  sky::SkyState scene(const HostSnapshot* host, Clock::time_point t);
  // The eye's adaptation as it is now, then the displays' tone curves and shown layers.
  void adaptAndMap(sky::SkyState& s) const;
  // Steps the eye to the scene `s` of host message `host` (reset at a jump of the scene).
  void stepEye(const HostSnapshot& host, const sky::SkyState& s);

  const NodeConfig& config_;
  NodeStats& stats_;
  atmosphere::AtmosphereUpdater* updater_;
  HostAtmosphere hostAtmosphere_;
  sky::SkyConditions conditions_;  // the configured sky with the newest atmosphere
  // The visibility the air shows (km; 0: the tables' own): the configuration's until the host
  // sends another; below the tables' it is the haze layer (physics/weather/fog_layer.h), which
  // follows the host at once while the tables take their time.
  double visibilityKm_ = 0.0;
  double lastHostVisibilityM_;
  std::uint64_t generation_ = 0;   // the updater's initial model is the configuration's
  sky::SkyStateCaches caches_;
  sky::CloudLayers loggedClouds_{};  // the cloud layers last logged (logClouds)
  std::vector<sky::DisplayParams> displays_;  // of the node's channels: their tone curves
  sky::eye::EyeAdaptation eye_;
  std::optional<Clock::time_point> lastBuild_;
  std::optional<Clock::time_point> lastHostMessage_;  // `received` of the last host state stepped to
  std::optional<sky::ObserverState> lastHostObserver_;
  bool hostInstantsOnly_ = false;
};

}  // namespace skyig::services
