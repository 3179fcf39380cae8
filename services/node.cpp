#include "services/node.h"

#include "protocol/cigi/encoder.h"
#include "sky/atmosphere/updater.h"
#include "render/gl/gl_context.h"
#include "render/gl/glfw_window.h"
#include "render/sky_renderer.h"
#include "services/atmosphere_loader.h"
#include "services/can_receiver.h"
#include "services/cigi_receiver.h"
#include "services/host_atmosphere.h"
#include "services/recorder.h"
#include "services/state_dump.h"

#include <glad/gl.h>
#include <spdlog/spdlog.h>

#include <fstream>
#include <memory>
#include <thread>
#include <unistd.h>

namespace skyig::services {

namespace {

using namespace std::chrono_literals;

// The observer a frame shows: the host's state evaluated at `t`, or the configuration's
// observer until the host has said anything.
sky::ObserverState observerAt(const NodeConfig& config, const HostSnapshot* host, Clock::time_point t) {
  sky::ObserverState o = config.observer;
  if (!host) return o;
  if (host->state.ownshipValid) {
    const Ownship s = host->predictor.at(t);
    o.latitudeDeg = s.latitudeDeg;
    o.longitudeDeg = s.longitudeDeg;
    o.heightM = s.altitudeM;
    o.attitude = {s.yawDeg, s.pitchDeg, s.rollDeg};
  }
  if (const auto utc = host->utcAt(t)) o.utc = *utc;
  return o;
}

// The configured sky with what the host sets of it (the star field intensity).
// The sky's conditions with the host's star-field intensity (CIGI Celestial Sphere Control).
sky::SkyConditions withHostStars(sky::SkyConditions c, const HostSnapshot* host) {
  if (host) c.starFieldIntensity = host->state.starFieldIntensity;
  return c;
}

// The node's channels with the host's view overrides applied.
std::vector<sky::ChannelConfig> channelsFor(const std::vector<sky::ChannelConfig>& base, const HostSnapshot* host) {
  std::vector<sky::ChannelConfig> channels = base;
  if (!host) return channels;
  for (const ViewOverride& v : host->state.views) {
    if (v.viewId >= channels.size()) continue;
    sky::ChannelConfig& c = channels[v.viewId];
    if (v.yawDeg) c.offset.yawDeg = *v.yawDeg;
    if (v.pitchDeg) c.offset.pitchDeg = *v.pitchDeg;
    if (v.rollDeg) c.offset.rollDeg = *v.rollDeg;
    if (v.leftDeg) c.frustum.leftDeg = *v.leftDeg;
    if (v.rightDeg) c.frustum.rightDeg = *v.rightDeg;
    if (v.upDeg) c.frustum.upDeg = *v.upDeg;
    if (v.downDeg) c.frustum.downDeg = *v.downDeg;
  }
  return channels;
}

// The physical sky's half of the worker: the host's visibility and humidity -> (debounced,
// validated) a request to the background updater -> its newest model in the next SkyStates
// (the renderer uploads it across frames, render/passes/physical_sky_pass.h).
class AtmosphereFollower {
 public:
  AtmosphereFollower(const NodeConfig& config, atmosphere::AtmosphereUpdater* updater)
      : config_(config),
        updater_(updater),
        host_(updater ? updater->current()->config().medium : atmosphere::Medium{}, config.sky.groundAlbedo) {}

  // Returns true when the sky's model changed (the conditions then carry the new one).
  bool update(const HostSnapshot* snapshot, sky::SkyConditions& conditions, NodeStats& stats, Clock::time_point now) {
    if (!updater_) return false;
    if (snapshot) {
      try {
        if (const auto c = host_.observe(snapshot->state.visibilityM, snapshot->state.humidityPct, now)) {
          spdlog::info("physical sky: visibility {:.0f} m, humidity {:.0f} %: new tables requested",
                       snapshot->state.visibilityM, snapshot->state.humidityPct);
          updater_->request(nodeModelConfig(config_, *c));
        }
      } catch (const std::invalid_argument& e) {
        stats.rejectedValues.fetch_add(1, std::memory_order_relaxed);
        spdlog::warn("host atmosphere not usable, keeping the last one: {}", e.what());
      }
    }
    const std::uint64_t generation = updater_->generation();
    if (generation == generation_) return false;
    generation_ = generation;
    conditions.atmosphere = updater_->current();
    return true;
  }

 private:
  const NodeConfig& config_;
  atmosphere::AtmosphereUpdater* updater_;
  HostAtmosphere host_;
  std::uint64_t generation_ = 0;  // the updater's initial model is the configuration's
};

// The worker: ephemeris, sky conditions and adaptation for the latest host state, published
// as an immutable SkyState. It never waits for the renderer, and a state it cannot use (a
// bad value that passed the decoder) is counted and the last good sky kept.
void workerLoop(const NodeOptions& opt, NodeStats& stats, Latest<HostSnapshot>& host,
                Latest<sky::SkyState>& sky, atmosphere::AtmosphereUpdater* updater, const std::atomic<bool>& stop) {
  sky::SkyConditions conditions = opt.config.sky;
  AtmosphereFollower follower(opt.config, updater);
  std::shared_ptr<const HostSnapshot> snapshot;
  std::uint64_t seen = ~0ull;
  ephemeris::EphemerisCache ephemerisCache;  // the worker's own: frame-to-frame interpolation
  auto lastSky = Clock::now() - 1h;
  auto lastStats = Clock::now();
  while (!stop.load(std::memory_order_relaxed)) {
    const auto now = Clock::now();
    const bool newHost = host.version() != seen;
    if (newHost) {
      seen = host.version();
      snapshot = host.get();
    }
    const bool newAtmosphere = follower.update(snapshot.get(), conditions, stats, now);
    // A new host state or atmosphere, or at least every 100 ms so the sun follows the clock.
    if (newHost || newAtmosphere || now - lastSky > 100ms) {
      try {
        sky.publish(sky::buildSkyState(observerAt(opt.config, snapshot.get(), now),
                                          withHostStars(conditions, snapshot.get()), std::nullopt, &ephemerisCache));
        stats.skyStates.fetch_add(1, std::memory_order_relaxed);
      } catch (const std::exception& e) {
        stats.rejectedValues.fetch_add(1, std::memory_order_relaxed);
        spdlog::warn("host state not usable, keeping the last sky: {}", e.what());
      }
      lastSky = now;
    }
    if (!opt.statsPath.empty() && now - lastStats > std::chrono::duration<double>(opt.statsIntervalS)) {
      writeStatsFile(opt.statsPath, stats);
      lastStats = now;
    }
    std::this_thread::sleep_for(1ms);
  }
}

// What renders: one headless context for every channel, or one window per channel.
class Display {
 public:
  Display(const NodeOptions& opt, const std::vector<sky::ChannelConfig>& channels) : headless_(opt.headless) {
    if (headless_) {
      context_ = render::createHeadlessContext();
      renderers_.push_back(std::make_unique<render::SkyRenderer>());
      return;
    }
    for (const auto& c : channels) {
      render::WindowOptions w;
      w.title = "skyig " + opt.config.nodeName + " / " + c.name;
      w.width = c.width;
      w.height = c.height;
      w.shareWith = windows_.empty() ? nullptr : windows_.front().get();
      if (!c.monitor.empty()) w.fullscreenMonitor = c.monitor;
      windows_.push_back(std::make_unique<render::GlfwWindowContext>(w));
      renderers_.push_back(std::make_unique<render::SkyRenderer>());  // VAOs and FBOs are per context
    }
  }

  const render::GlInfo& info() const { return headless_ ? context_->info() : windows_.front()->info(); }
  bool closeRequested() const {
    for (const auto& w : windows_)
      if (w->closeRequested()) return true;
    return false;
  }

  void draw(const sky::SkyState& state, const std::vector<sky::ChannelConfig>& channels) {
    for (std::size_t i = 0; i < channels.size(); ++i) {
      if (headless_) {
        renderers_.front()->draw(state, channels[i]);
        continue;
      }
      windows_[i]->makeCurrent();
      renderers_[i]->draw(state, channels[i]);
      renderers_[i]->presentToDefaultFramebuffer(channels[i].width, channels[i].height);
      windows_[i]->swapBuffers();
    }
    if (headless_) glFinish();  // the frame ends when its pixels exist
    else render::pollWindowEvents();
  }

 private:
  bool headless_;
  std::unique_ptr<render::GlContext> context_;
  std::vector<std::unique_ptr<render::GlfwWindowContext>> windows_;
  std::vector<std::unique_ptr<render::SkyRenderer>> renderers_;
};

std::uint32_t ticks10us(Clock::duration d) {
  return static_cast<std::uint32_t>(std::chrono::duration_cast<std::chrono::microseconds>(d).count() / 10);
}

}  // namespace

// Threads that are told to stop and joined however the scope is left (an exception included).
class ThreadGroup {
 public:
  explicit ThreadGroup(std::atomic<bool>& stop) : stop_(stop) {}
  ~ThreadGroup() {
    stop_ = true;
    for (auto& t : threads_) t.join();
  }
  ThreadGroup(const ThreadGroup&) = delete;
  ThreadGroup& operator=(const ThreadGroup&) = delete;
  template <typename F>
  void start(F&& f) {
    threads_.emplace_back(std::forward<F>(f));
  }

 private:
  std::atomic<bool>& stop_;
  std::vector<std::thread> threads_;
};

// A file descriptor closed with its scope.
struct OwnedFd {
  int fd = -1;
  ~OwnedFd() {
    if (fd >= 0) ::close(fd);
  }
};

int runNode(const NodeOptions& opt, NodeStats& stats, const std::atomic<bool>& externalStop) {
  std::atomic<bool> stop{false};
  Latest<HostSnapshot> host;
  Latest<sky::SkyState> sky;
  const auto start = Clock::now();

  // Everything that can fail (sockets, SocketCAN, the recording file, the first sky) is set
  // up before any thread starts.
  UdpSocket udp(opt.listen, opt.multicastGroup);  // always: Start of Frame goes out through it
  spdlog::info("listening for CIGI on {}", udp.localEndpoint().toString());
  CigiReceiver cigi(stats, host);
  std::unique_ptr<PcapRecorder> recorder;
  if (!opt.recordPath.empty()) {
    try {
      recorder = std::make_unique<PcapRecorder>(opt.recordPath, udp.localEndpoint());
    } catch (const std::runtime_error& e) {
      throw ConfigError(std::string("--record: ") + e.what());  // a bad path: say so before serving
    }
    cigi.setRecorder(recorder.get());
    spdlog::info("recording the host's datagrams to {}", opt.recordPath);
  }
  OwnedFd ownedCan;
  if (opt.canInterface) ownedCan.fd = openSocketCan(*opt.canInterface);
  const int canFd = opt.canInterface ? ownedCan.fd : opt.canFd;
  std::unique_ptr<CanReceiver> can;
  if (canFd >= 0) can = std::make_unique<CanReceiver>(canFd, opt.config.canIdentifiers, stats, host);
  // The physical sky follows the host's visibility and humidity through a background updater
  // (from the cache the configuration's tables were just loaded from).
  std::unique_ptr<atmosphere::AtmosphereUpdater> updater;
  NodeConfig config = opt.config;
  if (config.sky.model == sky::SkyModel::Physical) {
    updater = std::make_unique<atmosphere::AtmosphereUpdater>(nodeModelConfig(config, {}),
                                                              cacheDirectory(config.atmosphere));
    if (!config.sky.atmosphere) config.sky.atmosphere = updater->current();
  }
  NodeOptions workerOptions = opt;
  workerOptions.config = config;
  sky.publish(sky::buildSkyState(config.observer, config.sky));  // frame 0 already has a sky

  {
    ThreadGroup threads(stop);  // inside what the threads use: joined before any of it goes
    threads.start([&] { cigi.run(udp, stop); });
    if (can) threads.start([&] { can->run(stop); });
    threads.start([&] { workerLoop(workerOptions, stats, host, sky, updater.get(), stop); });

    const auto baseChannels = opt.config.channelsOf(opt.config.nodeName);
    if (baseChannels.empty()) throw ConfigError("node \"" + opt.config.nodeName + "\" has no channels in the configuration");
    Display display(opt, baseChannels);
    spdlog::info("rendering {} channel(s) on {}", baseChannels.size(), display.info().renderer);
    std::unique_ptr<StateDump> dump = opt.dumpStatePath.empty() ? nullptr : std::make_unique<StateDump>(opt.dumpStatePath);
    const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / opt.frameRateHz));
    auto next = Clock::now();
    std::uint64_t hostVersionShown = 0;
    Clock::time_point lastArrivalShown{};
    std::vector<std::uint8_t> sof;
    for (std::uint64_t frame = 0; !externalStop && (opt.frames == 0 || frame < opt.frames); ++frame) {
      if (opt.synchronous) {
        // Frame N follows the host's frame N; a silent host does not freeze the IG.
        const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(opt.syncTimeoutS));
        while (host.version() == hostVersionShown && Clock::now() < deadline && !externalStop)
          std::this_thread::sleep_for(50us);
        if (host.version() == hostVersionShown) stats.syncTimeouts.fetch_add(1, std::memory_order_relaxed);
      } else if (opt.headless) {
        std::this_thread::sleep_until(next);
        next = std::max(next + period, Clock::now() - period);
      }
      hostVersionShown = host.version();
      const auto snapshot = host.get();
      const auto frameStart = Clock::now();
      sky::SkyState state = *sky.get();
      state.observer = observerAt(opt.config, snapshot.get(), frameStart);  // attitude of this frame
      const auto channels = channelsFor(baseChannels, snapshot.get());
      display.draw(state, channels);
      const auto frameEnd = Clock::now();
      stats.frames.fetch_add(1, std::memory_order_relaxed);
      stats.frameTime.add(std::chrono::duration<double, std::micro>(frameEnd - frameStart).count());
      if (snapshot && snapshot->state.received != lastArrivalShown) {
        stats.arrivalToFrameEnd.add(std::chrono::duration<double, std::micro>(frameEnd - snapshot->state.received).count());
        lastArrivalShown = snapshot->state.received;
      }

      // Start of Frame: to --reply-to, else back to the host's address on the reply port.
      std::optional<sockaddr_in> to;
      if (opt.replyTo) to = toSockaddr(*opt.replyTo);
      else if (snapshot && snapshot->sender) {
        to = *snapshot->sender;
        to->sin_port = htons(opt.replyPort);
      }
      if (to) {
        protocol::cigi::StartOfFrame s;
        s.igFrameNumber = static_cast<std::uint32_t>(frame);
        s.lastHostFrameNumber = snapshot ? snapshot->state.hostFrame : 0;
        s.timestamp = ticks10us(frameEnd - start);
        s.timestampValid = true;
        const protocol::cigi::Packet packets[] = {s};
        if (protocol::cigi::encodeMessage(packets, protocol::ByteOrder::big, sof).empty() && udp.sendTo(sof, *to))
          stats.startOfFrameSent.fetch_add(1, std::memory_order_relaxed);
      }
      if (dump) dump->write(frame, snapshot.get(), state);
      if (!opt.headless && display.closeRequested()) break;
    }
  }  // the threads are joined here
  if (!opt.statsPath.empty()) writeStatsFile(opt.statsPath, stats);  // the final counters, once
  return 0;
}

}  // namespace skyig::services
