#include "node/record/replay.h"

#include "render/gl/gl_context.h"
#include "render/image_io.h"
#include "render/sky_renderer.h"
#include "node/transport/can_receiver.h"
#include "node/transport/cigi_receiver.h"
#include "node/record/recording_source.h"
#include "node/frame/frame_files.h"
#include "node/frame/frame_metadata.h"
#include "node/frame/sky_worker.h"
#include "node/frame/state_dump.h"
#include "node/common/warning_throttle.h"
#include "node/config/node_tables.h"

#include <glad/gl.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <thread>

namespace skyig::services {

namespace {

using Ns = std::chrono::nanoseconds;

// Recording time as the node's clock: arrival instants are synthetic, so everything
// downstream (extrapolation, the sim clock) sees the recording's timing, not this machine's.
Clock::time_point at(std::int64_t ns) { return Clock::time_point(std::chrono::duration_cast<Clock::duration>(Ns(ns))); }

struct Bound {
  std::optional<std::uint64_t> frame;
  std::optional<ephemeris::UtcTime> utc;
};

Bound parseBound(const std::optional<std::string>& text, const char* flag) {
  Bound b;
  if (!text) return b;
  if (text->find('T') != std::string::npos) {
    b.utc = ephemeris::parseIso8601Utc(*text);
    if (!b.utc) throw ConfigError(std::string(flag) + ": expected a frame number or a UTC time like 2026-06-21T19:30:00Z, got \"" + *text + "\"");
  } else {
    char* end = nullptr;
    const unsigned long long f = std::strtoull(text->c_str(), &end, 10);
    if (text->empty() || *end != '\0') throw ConfigError(std::string(flag) + ": expected a frame number or a UTC time, got \"" + *text + "\"");
    b.frame = f;
  }
  return b;
}

// Sleeps until `t` (realtime pacing) in short steps, so that a stop is seen within 50 ms.
void sleepUntil(std::chrono::steady_clock::time_point t, const std::atomic<bool>* stop) {
  while (std::chrono::steady_clock::now() < t && !(stop && stop->load(std::memory_order_relaxed)))
    std::this_thread::sleep_until(std::min(t, std::chrono::steady_clock::now() + std::chrono::milliseconds(50)));
}

double julian(const ephemeris::UtcTime& t) { return ephemeris::julianDateUtc(t); }

bool before(const ephemeris::UtcTime& a, const ephemeris::UtcTime& b) { return julian(a) < julian(b); }

// Where a frame is within what was asked for, 0..1, for the progress bar: by sim time between
// --from and --to when --to is a time (the recording's clock cannot say when the host's clock
// gets there), else by recording time between the frames --from and --to name (the recording's
// ends without them).
class ReplaySpan {
 public:
  ReplaySpan(const Bound& from, const Bound& to, std::int64_t firstNs, std::int64_t lastNs, double frameRateHz)
      : from_(from), to_(to), startNs_(firstNs), endNs_(lastNs) {
    auto frameNs = [&](std::uint64_t k) {
      return firstNs + static_cast<std::int64_t>(static_cast<double>(k) * 1e9 / frameRateHz);
    };
    if (from.frame) startNs_ = std::min(lastNs, frameNs(*from.frame));
    if (to.frame) endNs_ = std::min(lastNs, frameNs(*to.frame));
  }
  double fraction(std::int64_t timeNs, const std::optional<sky::SkyState>& sky) {
    if (to_.utc) {
      if (!sky) return 0.0;
      const double now = julian(sky->observer.utc);
      if (!startUtc_) startUtc_ = from_.utc ? julian(*from_.utc) : now;
      const double span = julian(*to_.utc) - *startUtc_;
      return span > 0.0 ? std::clamp((now - *startUtc_) / span, 0.0, 1.0) : 1.0;
    }
    if (endNs_ <= startNs_) return 1.0;
    return std::clamp(static_cast<double>(timeNs - startNs_) / static_cast<double>(endNs_ - startNs_), 0.0, 1.0);
  }

 private:
  Bound from_, to_;
  std::int64_t startNs_, endNs_;
  std::optional<double> startUtc_;
};

// Decodes every event up to the frame's instant and runs the sky worker there: the work of one
// frame that does not need the GPU, the same as the node's worker and render threads do.
struct Frame {
  std::uint64_t number = 0;
  std::int64_t timeNs = 0;
  std::shared_ptr<const HostSnapshot> host;
  std::optional<sky::SkyState> sky;  // none: the last one stays (no new host state, or a bad one)
  FramePose pose;
  std::string error;  // a host state the sky could not use (kept: the previous sky is shown)
};

class Feeder {
 public:
  Feeder(const ReplayOptions& o, RecordingSource& source, atmosphere::AtmosphereUpdater* updater)
      : options_(o),
        source_(source),
        cigi_(stats_, latest_, o.config.host.session),
        can_(-1, o.config.canIdentifiers, stats_, latest_),
        worker_(o.config, updater, stats_),
        channels_(o.config.channelsOf(o.config.nodeName)) {
    cigi_.setViews(static_cast<std::size_t>(o.config.host.maxViews), channels_);
    haveEvent_ = source_.next(event_);
    firstNs_ = haveEvent_ ? event_.timeNs : 0;
  }
  bool exhausted() const { return !haveEvent_; }

  // The first frame shows the host's first place and time, not the configuration's: a
  // CANaerospace host sends each parameter in a CAN frame of its own, so its recording's first
  // record is a latitude alone. Records are fed until the host's state has a pose and a time,
  // or kFirstPoseWindowS of the recording has passed, and the first frame is at the last record
  // fed. A CIGI recording, whose first datagram states both, starts where it did.
  void startAtTheFirstPose() {
    auto complete = [&] {
      const std::shared_ptr<const HostSnapshot> h = latest_.get();
      return h && h->state.ownshipValid && h->state.timeValid;
    };
    const std::int64_t windowEndNs = firstNs_ + static_cast<std::int64_t>(kFirstPoseWindowS * 1e9);
    std::int64_t lastFedNs = firstNs_;
    while (haveEvent_ && event_.timeNs <= windowEndNs && !complete()) {
      lastFedNs = event_.timeNs;
      feedOne();
    }
    firstNs_ = lastFedNs;
  }
  std::int64_t firstNs() const { return firstNs_; }
  std::uint64_t events() const { return events_; }
  std::uint64_t gaps() const { return gaps_; }
  double gapSeconds() const { return gapSeconds_; }

  // Frame k's instant on the recording's clock: k frame periods after the first record, plus
  // the pauses skipped before it.
  std::int64_t frameTimeNs(std::uint64_t number) const {
    return firstNs_ + skippedNs_ + static_cast<std::int64_t>(std::llround(static_cast<double>(number) * 1e9 / options_.frameRateHz));
  }

  Frame prepare(std::uint64_t number) {
    if (number == 0) startAtTheFirstPose();
    Frame f;
    f.number = number;
    f.timeNs = frameTimeNs(number);
    while (haveEvent_ && event_.timeNs <= f.timeNs) feedOne();
    // A pause longer than --max-gap (a paused host, a corrupt timestamp far ahead): the next
    // frame is the next record's instant, not one of the 1/frame-rate steps through the pause.
    const auto maxGapNs = static_cast<std::int64_t>(options_.maxGapS * 1e9);
    if (haveEvent_ && options_.maxGapS > 0.0 && event_.timeNs - f.timeNs > maxGapNs) {
      const std::int64_t skip = event_.timeNs - frameTimeNs(number + 1);
      skippedNs_ += skip;
      ++gaps_;
      gapSeconds_ += static_cast<double>(skip) * 1e-9;
      spdlog::warn("replay: skipped {:.3f} s without records after record {} (longer than --max-gap {} s); frame {} "
                   "shows record {}",
                   static_cast<double>(skip) * 1e-9, lastRecord_, options_.maxGapS, number + 1, event_.record);
    }
    f.host = latest_.get();
    const Clock::time_point t = at(f.timeNs);
    // New tables for the host's visibility are waited for: the frame shows what the node shows
    // once they are built, whatever this machine's speed.
    const bool newAtmosphere = worker_.followAtmosphere(f.host.get(), t, /*wait=*/true);
    try {
      f.sky = worker_.step(f.host.get(), t, newAtmosphere || number == 0);
    } catch (const std::exception& e) {
      f.error = e.what();
    }
    f.pose = worker_.poseAt(f.host.get(), t, channels_);
    return f;
  }

 private:
  const ReplayOptions& options_;
  RecordingSource& source_;
  NodeStats stats_;
  Latest<HostSnapshot> latest_;
  CigiReceiver cigi_;
  CanReceiver can_;
  HostEvent event_;
  bool haveEvent_ = false;
  std::int64_t firstNs_ = 0;
  std::uint64_t events_ = 0;
  std::int64_t skippedNs_ = 0;
  std::uint64_t gaps_ = 0;
  double gapSeconds_ = 0.0;
  std::uint64_t lastRecord_ = 0;
  SkyWorker worker_;
  const std::vector<sky::ChannelConfig> channels_;  // the node's: view n of the host is the n-th

  static constexpr double kFirstPoseWindowS = 1.0;  // CANaerospace hosts send every parameter at 10 Hz or faster

  // The next record into its receiver (a CIGI datagram only from the replayed port, if one is set).
  void feedOne() {
    if (event_.kind == HostEvent::Kind::canFrame) {
      can_.handle(event_.frame, at(event_.timeNs));
    } else if (options_.port == 0 || event_.destinationPort == options_.port) {
      cigi_.handle(event_.payload, event_.from, at(event_.timeNs));
    }
    ++events_;
    lastRecord_ = event_.record;
    haveEvent_ = source_.next(event_);
  }
};

class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled), tty_(::isatty(2) != 0), start_(std::chrono::steady_clock::now()) {}
  // fraction: of the recording's duration replayed so far.
  void update(double fraction, std::uint64_t frame, bool force = false) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!force && now - last_ < std::chrono::milliseconds(tty_ ? 200 : 5000)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = fraction > 1e-6 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    const int width = 30, filled = static_cast<int>(fraction * width);
    std::fprintf(stderr, "%s[%.*s%*s] %5.1f%%  frame %llu  %.0f s elapsed, ~%.0f s left%s", tty_ ? "\r" : "",
                 filled, "==============================", width - filled, "", 100.0 * fraction,
                 static_cast<unsigned long long>(frame), elapsed, left, tty_ ? "" : "\n");
    if (force && tty_) std::fprintf(stderr, "\n");
  }

 private:
  bool enabled_, tty_;
  std::chrono::steady_clock::time_point start_, last_{};
};

ReplayResult sendRecording(const ReplayOptions& o) {
  RecordingSource source(o.recording, o.skipBad);
  if (source.format() == protocol::RecordingFormat::candump)
    throw ConfigError("--send re-transmits UDP recordings; replay a candump log onto a CAN bus with canplayer");
  UdpSocket socket({"0.0.0.0", 0});
  const sockaddr_in to = toSockaddr(*o.sendTo);
  ReplayResult r;
  HostEvent e;
  std::optional<std::int64_t> first;
  const auto start = std::chrono::steady_clock::now();
  while (source.next(e)) {
    if (o.stop && o.stop->load(std::memory_order_relaxed)) {
      r.stopped = true;
      break;
    }
    if (o.port != 0 && e.destinationPort != o.port) continue;
    if (!first) first = e.timeNs;
    if (o.realtime) sleepUntil(start + Ns(e.timeNs - *first), o.stop);
    socket.sendTo(e.payload, to);
    ++r.events;
  }
  r.skippedRecords = source.skipped();
  r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

}  // namespace

ReplayResult replay(const ReplayOptions& o) {
  if (o.sendTo) return sendRecording(o);
  const Bound from = parseBound(o.from, "--from"), to = parseBound(o.to, "--to");
  // Which of the node's channels are written (the host's views apply to all of them first).
  const std::vector<sky::ChannelConfig> nodeChannels = o.config.channelsOf(o.config.nodeName);
  std::vector<bool> wanted(nodeChannels.size(), o.allChannels);
  if (!o.channel.empty()) {
    for (std::size_t i = 0; i < nodeChannels.size(); ++i) wanted[i] = nodeChannels[i].name == o.channel;
    if (std::find(wanted.begin(), wanted.end(), true) == wanted.end())
      throw ConfigError("--channel: no channel named \"" + o.channel + "\"");
  } else if (!wanted.empty()) {
    wanted[0] = true;
  }
  const std::size_t written = static_cast<std::size_t>(std::count(wanted.begin(), wanted.end(), true));
  if (!o.outDir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(o.outDir, ec);
    if (ec) throw render::ImageIoError("cannot create " + o.outDir + ": " + ec.message());
    render::checkWritable((std::filesystem::path(o.outDir) / "probe").string());
  }

  if (!o.dumpStatePath.empty()) render::checkWritable(o.dumpStatePath);
  RecordingSource source(o.recording, o.skipBad);
  // The last record's time, for the progress bar: a first pass over the file (cheap); none
  // over a stream (a FIFO), which can be read only once.
  std::int64_t lastNs = 0, firstNs = 0;
  if (source.seekable()) {
    RecordingSource scan(o.recording, true);
    HostEvent e;
    bool first = true;
    while (scan.next(e)) {
      if (first) firstNs = e.timeNs, first = false;
      lastNs = std::max(lastNs, e.timeNs);
    }
  }
  const std::unique_ptr<atmosphere::AtmosphereUpdater> updater =
      makeAtmosphereUpdater(o.config, /*rateLimited=*/false, o.stop);
  Feeder feeder(o, source, updater.get());
  const auto context = render::createHeadlessContext();
  render::SkyRenderer renderer;
  std::unique_ptr<StateDump> dump = o.dumpStatePath.empty() ? nullptr : std::make_unique<StateDump>(o.dumpStatePath);
  Progress progress(o.progress);
  ReplaySpan span(from, to, firstNs, lastNs, o.frameRateHz);
  double shown = 0.0;  // the bar's last fraction
  ReplayResult result;
  const auto wallStart = std::chrono::steady_clock::now();
  std::optional<sky::SkyState> lastSky;
  FramePose lastPose;
  WarningThrottle badState;

  std::future<Frame> next = std::async(std::launch::async, [&] { return feeder.prepare(0); });
  for (std::uint64_t k = 0;; ++k) {
    Frame frame = next.get();
    const bool last = feeder.exhausted() && frame.timeNs >= lastNs;
    // The next frame's decoding and ephemeris run while this one renders.
    if (!last) next = std::async(std::launch::async, [&feeder, k] { return feeder.prepare(k + 1); });
    if (frame.sky) lastSky = frame.sky;
    lastPose = frame.pose;
    // Throttled on the recording's clock: a replay's log reads as the node's would have.
    if (std::uint64_t heldBack = 0; !frame.error.empty() && badState.allow(at(frame.timeNs), &heldBack))
      spdlog::warn("frame {}: host state not usable, keeping the last sky: {}{}", k, frame.error,
                   heldBack ? fmt::format(" ({} more since the last warning)", heldBack) : "");
    ++result.frames;
    const bool afterFrom = (!from.frame || k >= *from.frame) && (!from.utc || !lastSky || !before(lastSky->observer.utc, *from.utc));
    const bool pastTo = (to.frame && k > *to.frame) || (to.utc && lastSky && before(*to.utc, lastSky->observer.utc));
    result.stopped = o.stop && o.stop->load(std::memory_order_relaxed);
    if (pastTo || result.stopped) {
      if (!last) next.wait();
      break;
    }
    if (afterFrom && lastSky) {
      if (o.realtime) sleepUntil(wallStart + Ns(frame.timeNs - feeder.firstNs()), o.stop);
      // Only the frames written are drawn. The worker stepped at every host message all the same
      // (the eye, the weather and the tables are those of a replay that draws every frame), and
      // a frame not drawn still advances what the renderer carries from frame to frame (a new
      // table set's upload, slices per draw), so a written frame is byte for byte the one an
      // every-frame replay writes.
      const bool write = !o.outDir.empty() && k % static_cast<std::uint64_t>(o.every) == 0;
      for (std::size_t i = 0; i < lastPose.channels.size(); ++i) {
        if (!wanted[i]) continue;
        const sky::ChannelConfig& c = lastPose.channels[i];
        if (!write) {
          renderer.advance(*lastSky);
          continue;
        }
        renderer.draw(*lastSky, lastPose.attitude, c);
        const std::string stem = frameStem(o.outDir, k, lastSky->observer.utc, written > 1 ? c.name : "");
        render::ImageAttributes attributes = frameAttributes(*lastSky, lastPose.attitude, c);
        attributes["skyig:frame"] = static_cast<double>(k);  // an integer, exact to 2^53
        if (frame.host) attributes["skyig:host_frame"] = static_cast<double>(frame.host->state.hostFrame);
        attributes["skyig:recording"] = std::filesystem::path(o.recording).filename().string();
        result.imagesWritten +=
            static_cast<std::uint64_t>(writeFrameFiles(renderer, stem, c, o.writeExr, o.writePng, attributes));
      }
      if (write) {
        glFinish();  // the frame is done when its pixels are
        ++result.framesDrawn;
      }
      if (dump) dump->write(k, frame.host.get(), *lastSky, lastPose);
    }
    shown = span.fraction(frame.timeNs, lastSky);
    progress.update(shown, k);
    if (last) break;
  }
  progress.update(result.stopped ? shown : 1.0, result.frames, true);
  result.events = feeder.events();
  result.skippedGaps = feeder.gaps();
  result.skippedGapSeconds = feeder.gapSeconds();
  result.skippedRecords = source.skipped();
  for (const auto& m : source.skippedMessages()) spdlog::warn("skipped: {}", m);
  result.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  return result;
}

}  // namespace skyig::services
