#include "node/frame/sky_worker.h"
#include "physics/common/units.h"
#include "node/config/node_tables.h"
#include "physics/weather/cloud_layer.h"
#include "physics/weather/precipitation.h"

#include <spdlog/spdlog.h>

#include <array>
#include <span>
#include <stdexcept>

namespace skyig::services {

SkyWorker::SkyWorker(const NodeConfig& config, atmosphere::AtmosphereUpdater* updater, NodeStats& stats)
    : config_(config),
      stats_(stats),
      updater_(updater),
      hostAtmosphere_(updater ? updater->current()->config().medium : atmosphere::Medium{}, config.sky.groundAlbedo),
      conditions_(config.sky),
      visibilityKm_(config.atmosphere.visibilityKm.value_or(0.0)),
      lastHostVisibilityM_(HostState{}.visibilityM) {
  if (updater_ && !conditions_.atmosphere) conditions_.atmosphere = updater_->current();
  for (const sky::ChannelConfig& c : config.channelsOf(config.nodeName)) displays_.push_back(c.display);
}

bool SkyWorker::followAtmosphere(const HostSnapshot* host, Clock::time_point now, bool wait) {
  if (!updater_) return false;
  if (host) {
    try {
      const auto c = hostAtmosphere_.observe(host->state.visibilityM, host->state.humidityPct, now);
      if (host->state.visibilityM != lastHostVisibilityM_) {  // valid: observe() did not throw
        lastHostVisibilityM_ = host->state.visibilityM;
        visibilityKm_ = kmFromMetres(host->state.visibilityM);
      }
      if (c) {
        // Replay waits for the exact tables: no blend for it.
        const atmosphere::ModelConfig wanted = nodeModelConfig(config_, *c);
        const atmosphere::RequestAnswer a = updater_->request(wanted, /*blend=*/!wait);
        const double tablesKm = atmosphere::visibilityOf(wanted.medium);
        if (c->visibilityKm && *c->visibilityKm < tablesKm)  // the rest is the haze layer (nodeHaze)
          spdlog::info("physical sky: visibility {:.3g} km, humidity {:.0f} %: the {:.3g} km tables and a haze layer",
                       *c->visibilityKm, host->state.humidityPct, tablesKm);
        else
          spdlog::info("physical sky: visibility {:.3g} km, humidity {:.0f} %: new tables requested{}{}",
                       c->visibilityKm.value_or(0.0), host->state.humidityPct,
                       a.why.empty() ? "" : " (no blend: ", a.why.empty() ? "" : a.why + ")");
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
  const double km = atmosphere::visibilityOf(conditions_.atmosphere->config().medium);
  if (const auto& b = conditions_.atmosphere->blendOrigin(); b && b->clearerKm != b->hazierKm)
    spdlog::info("physical sky: visibility {:.3g} km: blending the {:.3g} and {:.3g} km tables until the exact ones are built",
                 km, b->hazierKm, b->clearerKm);
  else if (b)
    spdlog::info("physical sky: visibility {:.3g} km: showing the nearest step's, the {:.3g} km tables, until the exact ones are built",
                 km, b->clearerKm);
  else
    spdlog::info("physical sky: visibility {:.3g} km: its own tables are shown", km);
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

sky::SkyState SkyWorker::scene(const HostSnapshot* host, Clock::time_point t) {
  sky::SkyConditions c = conditions_;
  // CIGI Celestial Sphere Control: the host dims or hides the star field.
  if (host) c.starFieldIntensity = host->state.starFieldIntensity;
  // The air below the tables' visibility, and the host's ground fog (CIGI Weather Control layer
  // 0) and precipitation (layers 4-9) over the configuration's.
  if (c.atmosphere) c.haze = nodeHaze(config_, visibilityKm_);
  if (host && host->state.groundFog) c.fog = *host->state.groundFog;
  if (host) {
    std::array<sky::FogSpec, weather::kPrecipitationKinds> sent{};
    std::size_t n = 0;
    for (const auto& layer : host->state.precipitation)
      if (layer) sent[n++] = *layer;
    if (n > 0) c.precipitation = weather::combinedLayers(std::span(sent.data(), n));
    // Its cloud layers (layers 1-3), each over the configuration's once the host sent it.
    for (std::size_t i = 0; i < sky::kCloudLayers; ++i)
      if (host->state.clouds[i]) c.clouds[i] = *host->state.clouds[i];
  }
  // Each cloud layer once as it changes: what the node was given and draws.
  for (std::size_t i = 0; i < sky::kCloudLayers; ++i) {
    if (c.clouds[i] == loggedClouds_[i]) continue;
    spdlog::info("cloud layer {}: {}", i + 1,
                 weather::describe(c.clouds[i]));
    loggedClouds_[i] = c.clouds[i];
  }
  return sky::buildSkyState(observerAt(host, t), c, std::nullopt, &caches_);
}

void SkyWorker::adaptAndMap(sky::SkyState& s) const {
  if (config_.temporalAdaptation && eye_.started()) {
    s.worldAdaptationLuminance = eye_.level();
    s.adaptationGain = eye_.gain(s.sceneLuminance);
  }
  sky::mapForDisplays(s, displays_);
}

namespace {

// The host's own clock at a message: its IG Control timestamps when it sends them (the same on
// every node and in a replay), else the message's arrival.
double hostSeconds(const HostSnapshot& host) {
  if (host.cigiClock && host.cigiClock->haveTimestamp) return host.cigiClock->continuousAt(host.state.received);
  return std::chrono::duration<double>(host.state.received.time_since_epoch()).count();
}

// A new scene rather than the next moment of the same one: the sim clock jumped by more than
// ten minutes, or the ownship by more than 20 km (a scenario reset or a reposition). The eye
// then starts adapted to it, as a pilot would be.
bool isJump(const sky::ObserverState& a, const sky::ObserverState& b) {
  const double minutes = std::abs(ephemeris::julianDateUtc(a.utc) - ephemeris::julianDateUtc(b.utc)) * 1440.0;
  using skyig::kDeg;
  constexpr double kEarthM = 6371000.0;
  const double dLat = (b.latitudeDeg - a.latitudeDeg) * kDeg, dLon = (b.longitudeDeg - a.longitudeDeg) * kDeg;
  const double h = std::sin(dLat / 2) * std::sin(dLat / 2) +
                   std::cos(a.latitudeDeg * kDeg) * std::cos(b.latitudeDeg * kDeg) * std::sin(dLon / 2) * std::sin(dLon / 2);
  const double metres = 2.0 * kEarthM * std::asin(std::min(1.0, std::sqrt(h)));
  return minutes > 10.0 || metres > 20000.0 || std::abs(a.heightM - b.heightM) > 20000.0;
}

}  // namespace

std::optional<sky::SkyState> SkyWorker::step(const HostSnapshot* host, Clock::time_point now, bool force,
                                             Clock::duration refresh) {
  const bool newHost = host && host->state.updates > 0 && (!lastHostMessage_ || host->state.received != *lastHostMessage_);
  const bool hostSpoke = host && host->state.updates > 0;
  if (hostInstantsOnly_ && hostSpoke && !newHost && !force) return std::nullopt;
  if (!newHost && !force && lastBuild_ && now - *lastBuild_ < refresh) return std::nullopt;
  const Clock::time_point t = newHost || (hostInstantsOnly_ && hostSpoke) ? host->state.received : now;
  // The scene first, then the eye stepped to it, then its tone curves: built once per state.
  sky::SkyState s = scene(host, t);
  lastBuild_ = std::max(t, lastBuild_.value_or(t));
  if (newHost && config_.temporalAdaptation) {
    // The host messages published since the last one stepped, which this worker skipped (it
    // reads only the latest snapshot): the eye steps at each of them too, so what it integrated
    // does not depend on this machine's load.
    for (const std::shared_ptr<const HostSnapshot>& e : host->earlier)
      if (e->state.updates > 0 && (!lastHostMessage_ || e->state.received > *lastHostMessage_)) {
        const sky::SkyState skipped = scene(e.get(), e->state.received);
        stepEye(*e, skipped);
      }
    stepEye(*host, s);
  } else if (newHost) {
    lastHostMessage_ = host->state.received;
    lastHostObserver_ = s.observer;
  }
  adaptAndMap(s);
  return s;
}

void SkyWorker::stepEye(const HostSnapshot& host, const sky::SkyState& s) {
  const double hostTime = hostSeconds(host);
  if (lastHostObserver_ && isJump(*lastHostObserver_, s.observer)) eye_.reset(s.sceneLuminance, hostTime);
  else eye_.step(s.sceneLuminance, hostTime);
  lastHostMessage_ = host.state.received;
  lastHostObserver_ = s.observer;
}

FramePose SkyWorker::poseAt(const HostSnapshot* host, Clock::time_point t,
                            const std::vector<sky::ChannelConfig>& channels) const {
  FramePose pose{observerAt(host, t).attitude, channels};
  if (!host) return pose;
  // CIGI View Control, View Definition and Sensor Control: view n is the node's n-th channel.
  for (std::size_t id = 0; id < pose.channels.size(); ++id) {
    const ViewOverride* found = host->state.views.find(id);
    if (!found) continue;
    const ViewOverride& v = *found;
    sky::ChannelConfig& c = pose.channels[id];
    if (v.yawDeg) c.offset.yawDeg = *v.yawDeg;
    if (v.pitchDeg) c.offset.pitchDeg = *v.pitchDeg;
    if (v.rollDeg) c.offset.rollDeg = *v.rollDeg;
    if (v.leftDeg) c.frustum.leftDeg = *v.leftDeg;
    if (v.rightDeg) c.frustum.rightDeg = *v.rightDeg;
    if (v.upDeg) c.frustum.upDeg = *v.upDeg;
    if (v.downDeg) c.frustum.downDeg = *v.downDeg;
    // The goggle switched on renders its class's NVIS band; off, the eye's.
    if (v.sensorOn) c.band = *v.sensorOn ? c.goggle.nvisClass : sky::SpectralBand::Visible;
    if (v.automaticGain) c.goggle.automaticGain = *v.automaticGain;
    if (v.gain && *v.gain > 0.0) c.goggle.gain = *v.gain;
  }
  return pose;
}

}  // namespace skyig::services
