#include "node/node.h"

#include "protocol/cigi/encoder.h"
#include "tables/updater.h"
#include "render/sky_renderer.h"
#include "render/warm_up_states.h"
#include "node/config/node_tables.h"
#include "node/transport/can_receiver.h"
#include "node/frame/display_outputs.h"
#include "node/transport/cigi_receiver.h"
#include "node/frame/frame_files.h"
#include "node/frame/frame_timing.h"
#include "node/frame/degradation.h"
#include "node/frame/frame_metadata.h"
#include "node/config/projector_channel.h"
#include "node/frame/sky_worker.h"
#include "node/record/recorder.h"
#include "node/frame/state_dump.h"
#include "node/common/systemd_notify.h"
#include "node/common/warning_throttle.h"

#include <fmt/ranges.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <thread>
#include <unistd.h>

namespace skyig::services {

namespace {

using namespace std::chrono_literals;

// What the worker hands the render thread: an immutable SkyState and the host snapshot it was
// built from, so a frame's attitude, views, Start of Frame and state dump all come from the
// same host frame as its sky (never a newer snapshot's attitude over an older one's sky).
struct BuiltSky {
  sky::SkyState state;
  std::shared_ptr<const HostSnapshot> host;  // null before the host said anything
  std::uint64_t hostVersion = 0;             // Latest<HostSnapshot>::version() of `host`
};

// The worker thread: the latest host state -> SkyWorker -> a BuiltSky. It never waits for the
// renderer, and a state it cannot use (a bad value that passed the decoder) is counted and the
// last good sky kept.
void workerLoop(const NodeOptions& opt, NodeStats& stats, Latest<HostSnapshot>& host, Latest<BuiltSky>& sky,
                SkyWorker& worker, const std::atomic<bool>& stop) {
  std::shared_ptr<const HostSnapshot> snapshot;
  std::uint64_t seen = ~0ull;
  WarningThrottle badState;
  auto lastStats = Clock::now();
  while (!stop.load(std::memory_order_relaxed)) {
    const auto now = Clock::now();
    const bool newHost = host.version() != seen;
    if (newHost) {
      seen = host.version();
      snapshot = host.get();
    }
    const bool newAtmosphere = worker.followAtmosphere(snapshot.get(), now);
    // A new host state or atmosphere, or at least every 100 ms so the sun follows the clock.
    try {
      if (auto state = worker.step(snapshot.get(), now, newAtmosphere)) {
        sky.publish(BuiltSky{std::move(*state), snapshot, seen});
        stats.skyStates.fetch_add(1, std::memory_order_relaxed);
      }
    } catch (const std::exception& e) {
      stats.rejectedValues.fetch_add(1, std::memory_order_relaxed);
      if (std::uint64_t heldBack = 0; badState.allow(now, &heldBack))
        spdlog::warn("host state not usable, keeping the last sky: {}{}", e.what(),
                     heldBack ? fmt::format(" ({} more since the last warning)", heldBack) : "");
    }
    if (!opt.statsPath.empty() && now - lastStats > std::chrono::duration<double>(opt.statsIntervalS)) {
      writeStatsFile(opt.statsPath, stats);
      lastStats = now;
    }
    std::this_thread::sleep_for(1ms);
  }
}

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

namespace {

// The host's datagrams recorded as they arrive (--record), or null.
std::unique_ptr<PcapRecorder> openRecorder(const NodeOptions& opt, const UdpSocket& udp, CigiReceiver& cigi) {
  if (opt.recordPath.empty()) return nullptr;
  std::unique_ptr<PcapRecorder> recorder;
  try {
    recorder = std::make_unique<PcapRecorder>(opt.recordPath, udp.localEndpoint());
  } catch (const std::runtime_error& e) {
    throw ConfigError(std::string("--record: ") + e.what());  // a bad path: say so before serving
  }
  cigi.setRecorder(recorder.get());
  spdlog::info("recording the host's datagrams to {}", opt.recordPath);
  return recorder;
}

// --save-frames: the folder made and a file written in it before anything is served.
void prepareSaveFrames(const NodeOptions& opt) {
  if (opt.saveFramesDir.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(opt.saveFramesDir, ec);
  if (ec) throw ConfigError("--save-frames: cannot create " + opt.saveFramesDir + ": " + ec.message());
  render::checkWritable((std::filesystem::path(opt.saveFramesDir) / "probe").string());
}

// The node's channels as drawn: each projector calibration read here, before any window opens
// (a bad file stops the node with exit 2 naming it); a projector channel is drawn with its
// region's camera, at its projector's size.
struct NodeChannels {
  std::vector<sky::ChannelConfig> channels;
  std::vector<DisplayOutputs::Projector> projectors;
};

NodeChannels loadNodeChannels(const NodeConfig& config) {
  const auto configured = config.channelsOf(config.nodeName);
  if (configured.empty()) throw ConfigError("node \"" + config.nodeName + "\" has no channels in the configuration");
  NodeChannels out;
  for (const auto& c : configured) {
    ProjectorChannel pc = loadProjectorChannel(c, config.projectorOf(c.name));
    if (pc.projector)
      spdlog::info("channel {}: projector {} ({}x{})", c.name, pc.projector->source, pc.projector->width, pc.projector->height);
    out.channels.push_back(pc.channel);
    out.projectors.push_back(pc.projector);
  }
  return out;
}

// The run's timing in one line at exit (the statistics' rings: the last 8192 frames), its rate
// over the seconds from the first frame to the last (the start-up not counted).
void logRunTiming(const NodeStats& stats, double elapsedS) {
  const std::uint64_t frames = stats.frames.load();
  if (frames == 0) return;
  const nlohmann::json t = stats.frameTime.summary();
  auto ms = [&](const char* key) { return t.value(key, 0.0) / 1000.0; };
  spdlog::info("served {} frames in {:.1f} s ({:.1f} fps): frame p50 {:.1f} ms, p99 {:.1f} ms, max {:.1f} ms; {} over "
               "{:.1f} ms; {} Start of Frames sent",
               frames, elapsedS, elapsedS > 0.0 ? static_cast<double>(frames) / elapsedS : 0.0, ms("p50_us"),
               ms("p99_us"), ms("max_us"), stats.framesOverPeriod.load(), stats.targetPeriodUs.load() / 1000.0,
               stats.startOfFrameSent.load());
}

void logChannels(const NodeOptions& opt, const NodeChannels& nc, const DisplayOutputs& display) {
  spdlog::info("rendering {} channel(s) of node \"{}\" on {} ({})", nc.channels.size(), opt.config.nodeName,
               display.info().renderer, opt.headless ? "headless" : "windows");
  for (const auto& c : nc.channels)
    spdlog::info("channel {}: {}x{}, yaw {} pitch {} roll {}, frustum left {} right {} down {} up {} deg", c.name,
                 c.width, c.height, c.offset.yawDeg, c.offset.pitchDeg, c.offset.rollDeg, c.frustum.leftDeg,
                 c.frustum.rightDeg, c.frustum.downDeg, c.frustum.upDeg);
}

// The render thread's loop: paces the frames, draws every channel from the worker's latest
// sky, answers the host with Start of Frame, and dumps the state.
class FrameLoop {
 public:
  FrameLoop(const NodeOptions& opt, NodeStats& stats, Latest<BuiltSky>& sky, Latest<HostSnapshot>& host,
            const SkyWorker& worker, UdpSocket& udp, Clock::time_point start)
      : opt_(opt), stats_(stats), sky_(sky), host_(host), worker_(worker), udp_(udp), start_(start),
        period_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / opt.frameRateHz))),
        next_(Clock::now()), degrade_(opt.config.degrade),
        dump_(opt.dumpStatePath.empty() ? nullptr : std::make_unique<StateDump>(opt.dumpStatePath)) {}

  void run(const NodeChannels& nc, DisplayOutputs& display, const std::atomic<bool>& externalStop) {
    SystemdNotifier systemd = SystemdNotifier::fromEnvironment();  // Type=notify: ready after frame 0, then the watchdog
    std::vector<std::string> names;
    for (const auto& c : nc.channels) names.push_back(c.name);
    stats_.channelGpuTime.setChannels(names);
    stats_.targetPeriodUs = 1e6 / opt_.frameRateHz;
    timing_.emplace(names, 1.0 / opt_.frameRateHz);
    logDegradation();
    warmUp(display, nc, externalStop);
    lastLog_ = Clock::now();
    for (std::uint64_t frame = 0; !externalStop && (opt_.frames == 0 || frame < opt_.frames); ++frame) {
      waitForFrame(externalStop);
      const std::shared_ptr<const BuiltSky> built = sky_.get();
      hostVersionShown_ = built->hostVersion;
      const HostSnapshot* snapshot = built->host.get();
      if (snapshot) lastHostFrameShown_ = snapshot->state.hostFrame;
      const auto frameStart = Clock::now();
      // The state as the worker built it, seen with the attitude and views of this frame's
      // instant predicted from the same host snapshot. In synchronous mode that instant is the
      // host frame's own (the state was built at it too): every node shows host frame N alike,
      // whenever its own frame starts; otherwise the frame's start, so a slower host does not
      // judder.
      const Clock::time_point poseTime =
          opt_.synchronous && snapshot && snapshot->state.updates > 0 ? snapshot->state.received : frameStart;
      FramePose pose = worker_.poseAt(snapshot, poseTime, nc.channels);
      scaleChannels(pose.channels);
      draw(display, frame, *built, pose);
      const auto frameEnd = Clock::now();
      count(snapshot, frameStart, frameEnd);
      time(snapshot, frameStart, frameEnd, display.lastChannelGpuSeconds());
      if (!savesFiles(frame)) followBudget(frameStart, frameEnd, display);  // writing files is not the frame's work
      if (!firstStart_) firstStart_ = frameStart;
      lastEnd_ = frameEnd;
      sendStartOfFrame(frame, snapshot, frameStart, frameEnd);
      if (dump_)
        dump_->write(frame, snapshot, built->state, pose, std::chrono::duration<double>(frameEnd - frameStart).count(),
                     display.lastChannelGpuSeconds());
      systemd.frameDone(Clock::now());
      if (!opt_.headless && display.closeRequested()) break;
    }
  }

  // Seconds from the first frame's start to the last one's end (0 before a frame).
  double servedSeconds() const {
    return firstStart_ ? std::chrono::duration<double>(lastEnd_ - *firstStart_).count() : 0.0;
  }

 private:
  // Synchronous: frame N follows the host's frame N (its sky built from it), and a silent host
  // does not freeze the IG. Headless: the configured rate. Windows: the swap's.
  void waitForFrame(const std::atomic<bool>& externalStop) {
    if (opt_.synchronous) {
      const auto deadline =
          Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(opt_.syncTimeoutS));
      while (sky_.get()->hostVersion == hostVersionShown_ && Clock::now() < deadline && !externalStop)
        std::this_thread::sleep_for(50us);
      if (sky_.get()->hostVersion == hostVersionShown_ && !externalStop) {
        stats_.syncTimeouts.fetch_add(1, std::memory_order_relaxed);
        // The IG never leaves a lock-step host guessing: it says that it drew on without it.
        if (std::uint64_t heldBack = 0; syncWait_.allow(Clock::now(), &heldBack))
          spdlog::warn("synchronous: no new host frame within {:.0f} ms of host frame {}; drawing on with the last "
                       "one{}", 1e3 * opt_.syncTimeoutS, lastHostFrameShown_,
                       heldBack ? fmt::format(" ({} more such frames since the last warning)", heldBack) : "");
      }
    } else if (opt_.headless) {
      std::this_thread::sleep_until(next_);
      next_ = std::max(next_ + period_, Clock::now() - period_);
    }
  }

  void logDegradation() const {
    const DegradationSettings& d = opt_.config.degrade;
    if (!d.enabled) return;
    spdlog::info("degradation on: after {} frames in a row over {:.1f} ms, every channel drawn at {} of its size; "
                 "back up after {} frames that fit {:.0f}% of the period at the level above",
                 d.overFrames, 1e3 / opt_.frameRateHz, fmt::join(d.scales, ", then "), d.releaseFrames,
                 100.0 * d.releaseHeadroom);
  }

  // While degraded (node/frame/degradation.h) every channel is drawn at the level's scale of its
  // size, its frustum kept: one scale for the whole node, so no seam between its channels.
  void scaleChannels(std::vector<sky::ChannelConfig>& channels) const {
    const double scale = degrade_.scale();
    if (scale >= 1.0) return;
    for (sky::ChannelConfig& c : channels) {
      c.width = std::max(1, static_cast<int>(std::lround(c.width * scale)));
      c.height = std::max(1, static_cast<int>(std::lround(c.height * scale)));
    }
  }

  // The frame's work against the period: the larger of its channels' GPU time and its time less
  // the presentation (a window's swap waits for the vertical blank, which is not work).
  void followBudget(Clock::time_point frameStart, Clock::time_point frameEnd, const DisplayOutputs& display) {
    double gpuS = 0.0;
    for (double s : display.lastChannelGpuSeconds()) gpuS += s;
    const double workS =
        std::max(gpuS, std::chrono::duration<double>(frameEnd - frameStart).count() - display.lastPresentSeconds());
    const int change = degrade_.add(workS, 1.0 / opt_.frameRateHz);
    if (change == 0) return;
    (change > 0 ? stats_.resolutionDrops : stats_.resolutionRestores).fetch_add(1, std::memory_order_relaxed);
    stats_.resolutionScale = degrade_.scale();
    if (change > 0) spdlog::warn("cannot hold {:.0f} Hz: {}", opt_.frameRateHz, degrade_.lastReason());
    else spdlog::info("headroom at {:.0f} Hz: {}", opt_.frameRateHz, degrade_.lastReason());
  }

  bool savesFiles(std::uint64_t frame) const {
    return !opt_.saveFramesDir.empty() && frame % std::max<std::uint64_t>(opt_.saveEvery, 1) == 0;
  }

  // Every channel drawn; with --save-frames, every saveEvery-th frame's files written too.
  void draw(DisplayOutputs& display, std::uint64_t frame, const BuiltSky& built, const FramePose& pose) {
    if (!savesFiles(frame)) {
      display.draw(built.state, pose.attitude, pose.channels);
      return;
    }
    const HostSnapshot* snapshot = built.host.get();
    display.draw(built.state, pose.attitude, pose.channels,
                 [&](const render::SkyRenderer& r, const sky::ChannelConfig& c, const calibration::ProjectorCalibration* p) {
      const std::string stem =
          frameStem(opt_.saveFramesDir, frame, built.state.observer.utc, pose.channels.size() > 1 ? c.name : "");
      render::ImageAttributes attributes = frameAttributes(built.state, pose.attitude, c);
      attributes["skyig:frame"] = static_cast<double>(frame);  // an integer, exact to 2^53
      if (snapshot) attributes["skyig:host_frame"] = static_cast<double>(snapshot->state.hostFrame);
      writeFrameFiles(r, stem, c, true, true, attributes, p);
    });
  }

  void count(const HostSnapshot* snapshot, Clock::time_point frameStart, Clock::time_point frameEnd) {
    stats_.frames.fetch_add(1, std::memory_order_relaxed);
    stats_.frameTime.add(std::chrono::duration<double, std::micro>(frameEnd - frameStart).count());
    if (snapshot && snapshot->state.received != lastArrivalShown_) {
      stats_.arrivalToFrameEnd.add(std::chrono::duration<double, std::micro>(frameEnd - snapshot->state.received).count());
      lastArrivalShown_ = snapshot->state.received;
    }
  }

  // Compiled in the frame that first needs them, a light's or a weather's programs cost that
  // frame a second on llvmpipe: so before the first frame the node draws, nothing shown, the
  // states of its day (render/warm_up_states.h), and each state again with every channel's goggle
  // switched (on for an eye channel, off for a goggle one), as a host's Sensor Control may switch
  // it. A stop asked for meanwhile ends it between two draws.
  void warmUp(DisplayOutputs& display, const NodeChannels& nc, const std::atomic<bool>& externalStop) {
    const auto start = Clock::now();
    const std::shared_ptr<const BuiltSky> built = sky_.get();
    std::vector<sky::DisplayParams> displays;
    for (const auto& c : nc.channels) displays.push_back(c.display);
    const std::vector<sky::SkyState> states = render::warmUpStates(built->state, displays);
    const sky::Attitude attitude = worker_.poseAt(built->host.get(), start, nc.channels).attitude;
    std::vector<sky::ChannelConfig> switched = nc.channels;
    for (sky::ChannelConfig& c : switched) c.band = sky::isGoggle(c) ? sky::SpectralBand::Visible : c.goggle.nvisClass;
    for (const sky::SkyState& s : states) {
      for (const sky::Attitude& a : render::warmUpAttitudes(s, attitude)) {
        if (externalStop) return;
        display.warmUp(s, a, nc.channels);
      }
      if (externalStop) return;
      display.warmUp(s, attitude, switched);
    }
    spdlog::info("the programs of {} lights and weathers of the day compiled in {:.0f} ms", states.size(),
                 1000.0 * std::chrono::duration<double>(Clock::now() - start).count());
  }

  // The frame's timing: in the statistics, and in the info line every logIntervalS.
  void time(const HostSnapshot* snapshot, Clock::time_point frameStart, Clock::time_point frameEnd,
            const std::vector<double>& channelGpuS) {
    auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
    const double frameS = seconds(frameEnd - frameStart);
    std::optional<double> intervalS, hostAgeS;
    if (previousStart_) intervalS = seconds(frameStart - *previousStart_);
    previousStart_ = frameStart;
    if (snapshot && snapshot->state.updates > 0) hostAgeS = seconds(frameEnd - snapshot->state.received);
    if (frameS * 1e6 > stats_.targetPeriodUs.load()) stats_.framesOverPeriod.fetch_add(1, std::memory_order_relaxed);
    if (intervalS) stats_.frameInterval.add(*intervalS * 1e6);
    if (hostAgeS) stats_.shownHostAge.add(*hostAgeS * 1e6);
    for (std::size_t i = 0; i < channelGpuS.size(); ++i) stats_.channelGpuTime.add(i, channelGpuS[i] * 1e6);
    timing_->add(frameS, intervalS, channelGpuS, hostAgeS);
    if (opt_.logIntervalS > 0.0 && frameEnd - lastLog_ >= std::chrono::duration<double>(opt_.logIntervalS)) {
      spdlog::info("{}; {} Start of Frames sent", timing_->takeLogLine(), stats_.startOfFrameSent.load());
      lastLog_ = frameEnd;
    }
  }

  // Start of Frame: to the configured host (host.reply_to, --reply-to), else to the followed
  // host's address on the reply port while it is alive: only an allowed sender that won a
  // session is answered, and one datagram from a spoofed source gets at most a session gap's
  // worth of frames, never a stream.
  // The host is alive if its latest datagram (the receiver's, not the one the frame shows, which
  // the worker may still be catching up on) came within a session gap of the frame's start: a
  // frame that takes longer than the gap to draw (a slow node) still answers, as the CIGI ICD
  // asks of every frame in asynchronous mode; judged at the frame's end by the state shown, a
  // node slower than the gap never answered.
  void sendStartOfFrame(std::uint64_t frame, const HostSnapshot* snapshot, Clock::time_point frameStart,
                        Clock::time_point frameEnd) {
    std::optional<sockaddr_in> to;
    const std::shared_ptr<const HostSnapshot> latest = host_.get();
    if (opt_.replyTo) to = toSockaddr(*opt_.replyTo);
    else if (latest && latest->sender &&
             frameStart - latest->state.received <= std::chrono::duration<double>(opt_.config.host.session.sessionGapS))
      to = toSockaddr(Sender{latest->sender->address, opt_.replyPort});
    if (!to) return;
    protocol::cigi::StartOfFrame s;
    s.igFrameNumber = static_cast<std::uint32_t>(frame);
    s.lastHostFrameNumber = snapshot ? snapshot->state.hostFrame : 0;
    s.timestamp = ticks10us(frameEnd - start_);
    s.timestampValid = true;
    const protocol::cigi::Packet packets[] = {s};
    // In the host's CIGI version: a 4.0 host reads a 4.0 Start of Frame (its first packet tells
    // a CIGI 4 message by its 16-bit size and id), a 3.x host a 3.3 one. The version is the
    // receiver's latest, so a frame drawn before the sky shows the host's first datagram answers
    // in it too.
    const HostSnapshot* version = latest ? latest.get() : snapshot;
    const bool cigi4 = version && version->state.cigiMajorVersion == 4;
    const std::string error = cigi4 ? protocol::cigi::encodeMessage4(packets, protocol::ByteOrder::big, sof_)
                                    : protocol::cigi::encodeMessage(packets, protocol::ByteOrder::big, sof_);
    if (error.empty() && udp_.sendTo(sof_, *to)) stats_.startOfFrameSent.fetch_add(1, std::memory_order_relaxed);
  }

  const NodeOptions& opt_;
  NodeStats& stats_;
  Latest<BuiltSky>& sky_;
  Latest<HostSnapshot>& host_;  // the receiver's latest: whether the host is alive
  const SkyWorker& worker_;
  UdpSocket& udp_;
  const Clock::time_point start_;
  const Clock::duration period_;
  Clock::time_point next_;
  DegradationPolicy degrade_;
  std::unique_ptr<StateDump> dump_;
  std::uint64_t hostVersionShown_ = 0;
  std::uint32_t lastHostFrameShown_ = 0;
  WarningThrottle syncWait_;
  Clock::time_point lastArrivalShown_{};
  std::optional<FrameTimingWindow> timing_;
  std::optional<Clock::time_point> previousStart_;
  std::optional<Clock::time_point> firstStart_;  // of the first frame: the run's time excludes the start-up
  Clock::time_point lastEnd_{};
  Clock::time_point lastLog_{};
  std::vector<std::uint8_t> sof_;
};

}  // namespace

int runNode(const NodeOptions& opt, NodeStats& stats, const std::atomic<bool>& externalStop) {
  std::atomic<bool> stop{false};
  Latest<HostSnapshot> host;
  Latest<BuiltSky> sky;
  const auto start = Clock::now();

  // Everything that can fail (sockets, SocketCAN, the recording file, the first sky) is set
  // up before any thread starts.
  UdpSocket udp(opt.listen, opt.multicastGroup, opt.multicastInterface);  // always: Start of Frame goes out through it
  spdlog::info("listening for CIGI on {}{}", udp.localEndpoint().toString(),
               opt.multicastGroup ? fmt::format(", multicast group {} on interface {}", *opt.multicastGroup,
                                                opt.multicastInterface.value_or(opt.listen.address))
                                  : std::string());
  const NodeChannels channels = loadNodeChannels(opt.config);
  CigiReceiver cigi(stats, host, opt.config.host.session);
  cigi.setViews(static_cast<std::size_t>(opt.config.host.maxViews), channels.channels);
  const std::unique_ptr<PcapRecorder> recorder = openRecorder(opt, udp, cigi);
  prepareSaveFrames(opt);
  OwnedFd ownedCan;
  if (opt.canInterface) ownedCan.fd = openSocketCan(*opt.canInterface);
  const int canFd = opt.canInterface ? ownedCan.fd : opt.canFd;
  std::unique_ptr<CanReceiver> can;
  if (canFd >= 0) can = std::make_unique<CanReceiver>(canFd, opt.config.canIdentifiers, stats, host);
  if (opt.canInterface) spdlog::info("reading CANaerospace from {}", *opt.canInterface);
  // The physical sky follows the host's visibility and humidity through a background updater
  // (from the cache the configuration's tables were just loaded from).
  const std::unique_ptr<atmosphere::AtmosphereUpdater> updater = makeAtmosphereUpdater(opt.config, /*rateLimited=*/true, &externalStop);
  SkyWorker worker(opt.config, updater.get(), stats);  // the worker thread's: its caches are its own
  worker.setHostInstantsOnly(opt.synchronous);
  sky.publish(BuiltSky{worker.build(nullptr, Clock::now()), nullptr, 0});  // frame 0 already has a sky

  double servedS = 0.0;
  {
    ThreadGroup threads(stop);  // inside what the threads use: joined before any of it goes
    threads.start([&] { cigi.run(udp, stop); });
    if (can) threads.start([&] { can->run(stop); });
    threads.start([&] { workerLoop(opt, stats, host, sky, worker, stop); });
    DisplayOutputs display(opt.headless, opt.config.nodeName, channels.channels, channels.projectors);
    logChannels(opt, channels, display);
    FrameLoop loop(opt, stats, sky, host, worker, udp, start);
    loop.run(channels, display, externalStop);
    servedS = loop.servedSeconds();
  }  // the threads are joined here
  if (!opt.statsPath.empty()) writeStatsFile(opt.statsPath, stats);  // the final counters, once
  logRunTiming(stats, servedS);
  return 0;
}

}  // namespace skyig::services
