#include "services/node.h"

#include "protocol/cigi/encoder.h"
#include "sky/atmosphere/updater.h"
#include "render/sky_renderer.h"
#include "services/atmosphere_loader.h"
#include "services/can_receiver.h"
#include "services/display_outputs.h"
#include "services/cigi_receiver.h"
#include "services/frame_files.h"
#include "services/frame_metadata.h"
#include "services/projector_channel.h"
#include "services/sky_worker.h"
#include "services/recorder.h"
#include "services/state_dump.h"
#include "services/systemd_notify.h"
#include "services/warning_throttle.h"

#include <spdlog/spdlog.h>

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
  CigiReceiver cigi(stats, host, opt.config.host.session);
  cigi.setMaxViews(static_cast<std::size_t>(opt.config.host.maxViews));
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
  if (!opt.saveFramesDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(opt.saveFramesDir, ec);
    if (ec) throw ConfigError("--save-frames: cannot create " + opt.saveFramesDir + ": " + ec.message());
    render::checkWritable((std::filesystem::path(opt.saveFramesDir) / "probe").string());
  }
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

  {
    ThreadGroup threads(stop);  // inside what the threads use: joined before any of it goes
    threads.start([&] { cigi.run(udp, stop); });
    if (can) threads.start([&] { can->run(stop); });
    threads.start([&] { workerLoop(opt, stats, host, sky, worker, stop); });

    const auto configured = opt.config.channelsOf(opt.config.nodeName);
    if (configured.empty()) throw ConfigError("node \"" + opt.config.nodeName + "\" has no channels in the configuration");
    // Each channel's projector calibration is read here, before any window opens: a bad file
    // stops the node with exit 2 naming it. A projector channel is drawn with its region's
    // camera, at its projector's size.
    std::vector<sky::ChannelConfig> baseChannels;
    std::vector<DisplayOutputs::Projector> projectors;
    for (const auto& c : configured) {
      ProjectorChannel pc = loadProjectorChannel(c, opt.config.projectorOf(c.name));
      if (pc.projector)
        spdlog::info("channel {}: projector {} ({}x{})", c.name, pc.projector->source, pc.projector->width, pc.projector->height);
      baseChannels.push_back(pc.channel);
      projectors.push_back(pc.projector);
    }
    DisplayOutputs display(opt.headless, opt.config.nodeName, baseChannels, projectors);
    spdlog::info("rendering {} channel(s) of node \"{}\" on {} ({})", baseChannels.size(), opt.config.nodeName,
                 display.info().renderer, opt.headless ? "headless" : "windows");
    for (const auto& c : baseChannels)
      spdlog::info("channel {}: {}x{}, yaw {} pitch {} roll {}, frustum left {} right {} down {} up {} deg", c.name,
                   c.width, c.height, c.offset.yawDeg, c.offset.pitchDeg, c.offset.rollDeg, c.frustum.leftDeg,
                   c.frustum.rightDeg, c.frustum.downDeg, c.frustum.upDeg);
    std::unique_ptr<StateDump> dump = opt.dumpStatePath.empty() ? nullptr : std::make_unique<StateDump>(opt.dumpStatePath);
    const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / opt.frameRateHz));
    auto next = Clock::now();
    std::uint64_t hostVersionShown = 0;
    Clock::time_point lastArrivalShown{};
    std::vector<std::uint8_t> sof;
    SystemdNotifier systemd = SystemdNotifier::fromEnvironment();  // Type=notify: ready after frame 0, then the watchdog
    for (std::uint64_t frame = 0; !externalStop && (opt.frames == 0 || frame < opt.frames); ++frame) {
      if (opt.synchronous) {
        // Frame N follows the host's frame N (its sky built from it); a silent host does not
        // freeze the IG.
        const auto deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(opt.syncTimeoutS));
        while (sky.get()->hostVersion == hostVersionShown && Clock::now() < deadline && !externalStop)
          std::this_thread::sleep_for(50us);
        if (sky.get()->hostVersion == hostVersionShown) stats.syncTimeouts.fetch_add(1, std::memory_order_relaxed);
      } else if (opt.headless) {
        std::this_thread::sleep_until(next);
        next = std::max(next + period, Clock::now() - period);
      }
      const std::shared_ptr<const BuiltSky> built = sky.get();
      hostVersionShown = built->hostVersion;
      const HostSnapshot* snapshot = built->host.get();
      const auto frameStart = Clock::now();
      // The state as the worker built it, seen with the attitude and views of this frame's
      // instant predicted from the same host snapshot. In synchronous mode that instant is the
      // host frame's own (the state was built at it too): every node shows host frame N alike,
      // whenever its own frame starts; otherwise the frame's start, so a slower host does not
      // judder.
      const Clock::time_point poseTime =
          opt.synchronous && snapshot && snapshot->state.updates > 0 ? snapshot->state.received : frameStart;
      const FramePose pose = worker.poseAt(snapshot, poseTime, baseChannels);
      if (!opt.saveFramesDir.empty() && frame % std::max<std::uint64_t>(opt.saveEvery, 1) == 0) {
        display.draw(built->state, pose.attitude, pose.channels,
                     [&](const render::SkyRenderer& r, const sky::ChannelConfig& c, const calibration::ProjectorCalibration* p) {
          const std::string stem = frameStem(opt.saveFramesDir, frame, built->state.observer.utc,
                                             pose.channels.size() > 1 ? c.name : "");
          render::ImageAttributes attributes = frameAttributes(built->state, pose.attitude, c);
          attributes["skyig:frame"] = static_cast<double>(frame);  // an integer, exact to 2^53
          if (snapshot) attributes["skyig:host_frame"] = static_cast<double>(snapshot->state.hostFrame);
          writeFrameFiles(r, stem, c, true, true, attributes, p);
        });
      } else {
        display.draw(built->state, pose.attitude, pose.channels);
      }
      const auto frameEnd = Clock::now();
      stats.frames.fetch_add(1, std::memory_order_relaxed);
      stats.frameTime.add(std::chrono::duration<double, std::micro>(frameEnd - frameStart).count());
      if (snapshot && snapshot->state.received != lastArrivalShown) {
        stats.arrivalToFrameEnd.add(std::chrono::duration<double, std::micro>(frameEnd - snapshot->state.received).count());
        lastArrivalShown = snapshot->state.received;
      }

      // Start of Frame: to the configured host (host.reply_to, --reply-to), else to the
      // followed host's address on the reply port while it is alive: only an allowed sender
      // that won a session is answered, and one datagram from a spoofed source gets at most a
      // session gap's worth of frames, never a stream.
      std::optional<sockaddr_in> to;
      if (opt.replyTo) to = toSockaddr(*opt.replyTo);
      else if (snapshot && snapshot->sender &&
               frameEnd - snapshot->state.received <=
                   std::chrono::duration<double>(opt.config.host.session.sessionGapS)) {
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
        // In the host's CIGI version: a 4.0 host reads a 4.0 Start of Frame (its first packet
        // tells a CIGI 4 message by its 16-bit size and id), a 3.x host a 3.3 one.
        const bool cigi4 = snapshot && snapshot->state.cigiMajorVersion == 4;
        const std::string error = cigi4 ? protocol::cigi::encodeMessage4(packets, protocol::ByteOrder::big, sof)
                                        : protocol::cigi::encodeMessage(packets, protocol::ByteOrder::big, sof);
        if (error.empty() && udp.sendTo(sof, *to))
          stats.startOfFrameSent.fetch_add(1, std::memory_order_relaxed);
      }
      if (dump) dump->write(frame, snapshot, built->state, pose);
      systemd.frameDone(Clock::now());
      if (!opt.headless && display.closeRequested()) break;
    }
  }  // the threads are joined here
  if (!opt.statsPath.empty()) writeStatsFile(opt.statsPath, stats);  // the final counters, once
  return 0;
}

}  // namespace skyig::services
