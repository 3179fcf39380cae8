#include "services/sky_worker.h"

#include <spdlog/spdlog.h>

#include <stdexcept>

namespace skyig::services {

SkyWorker::SkyWorker(const NodeConfig& config, atmosphere::AtmosphereUpdater* updater, NodeStats& stats)
    : config_(config),
      stats_(stats),
      updater_(updater),
      hostAtmosphere_(updater ? updater->current()->config().medium : atmosphere::Medium{}, config.sky.groundAlbedo),
      conditions_(config.sky) {
  if (updater_ && !conditions_.atmosphere) conditions_.atmosphere = updater_->current();
}

bool SkyWorker::followAtmosphere(const HostSnapshot* host, Clock::time_point now, bool wait) {
  if (!updater_) return false;
  if (host) {
    try {
      if (const auto c = hostAtmosphere_.observe(host->state.visibilityM, host->state.humidityPct, now)) {
        spdlog::info("physical sky: visibility {:.0f} m, humidity {:.0f} %: new tables requested",
                     host->state.visibilityM, host->state.humidityPct);
        updater_->request(nodeModelConfig(config_, *c));
        if (wait) updater_->waitIdle();
      }
    } catch (const std::invalid_argument& e) {
      stats_.rejectedValues.fetch_add(1, std::memory_order_relaxed);
      spdlog::warn("host atmosphere not usable, keeping the last one: {}", e.what());
    }
  }
  const std::uint64_t generation = updater_->generation();
  if (generation == generation_) return false;
  generation_ = generation;
  conditions_.atmosphere = updater_->current();
  return true;
}

sky::ObserverState SkyWorker::observerAt(const HostSnapshot* host, Clock::time_point t) const {
  sky::ObserverState o = config_.observer;
  if (!host) return o;
  if (host->state.ownshipValid) static_cast<sky::Ownship&>(o) = host->predictor.at(t);
  if (const auto utc = host->utcAt(t)) o.utc = *utc;
  o.pressureHpa = host->state.pressureHpa;
  o.temperatureC = host->state.temperatureC;
  return o;
}

sky::SkyState SkyWorker::build(const HostSnapshot* host, Clock::time_point t) {
  sky::SkyConditions c = conditions_;
  // CIGI Celestial Sphere Control: the host dims or hides the star field.
  if (host) c.starFieldIntensity = host->state.starFieldIntensity;
  return sky::buildSkyState(observerAt(host, t), c, std::nullopt, &caches_);
}

FramePose SkyWorker::poseAt(const HostSnapshot* host, Clock::time_point t,
                            const std::vector<sky::ChannelConfig>& channels) const {
  FramePose pose{observerAt(host, t).attitude, channels};
  if (!host) return pose;
  // CIGI View Control and View Definition: view n is the node's n-th channel.
  for (const ViewOverride& v : host->state.views) {
    if (v.viewId >= pose.channels.size()) continue;
    sky::ChannelConfig& c = pose.channels[v.viewId];
    if (v.yawDeg) c.offset.yawDeg = *v.yawDeg;
    if (v.pitchDeg) c.offset.pitchDeg = *v.pitchDeg;
    if (v.rollDeg) c.offset.rollDeg = *v.rollDeg;
    if (v.leftDeg) c.frustum.leftDeg = *v.leftDeg;
    if (v.rightDeg) c.frustum.rightDeg = *v.rightDeg;
    if (v.upDeg) c.frustum.upDeg = *v.upDeg;
    if (v.downDeg) c.frustum.downDeg = *v.downDeg;
  }
  return pose;
}

}  // namespace skyig::services
