#include "commands/replay_command.h"

#include "node/transport/can_receiver.h"
#include "commands/common_options.h"
#include "node/record/recorder.h"
#include "node/record/replay.h"
#include "render/output_file.h"
#include "node/config/sky_data.h"
#include "node/common/stop_signal.h"
#include "physics/atmosphere/precompute/precompute_control.h"

#include <poll.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <memory>

namespace skyig::services {

namespace {

struct RecordOptions {
  std::string listen = "0.0.0.0:8004";
  std::string multicastGroup;
  std::string out;
  std::string canInterface;
  std::string canOut;
  double durationS = 0.0;
  std::uint64_t count = 0;
};

int runRecord(const RecordOptions& o) {
  const StopOnSignal signals;
  if (o.out.empty() && o.canOut.empty()) throw ConfigError("record: give --out FILE.pcap and/or --can IF --can-out FILE.log");
  if (!o.canOut.empty() && o.canInterface.empty()) throw ConfigError("--can-out needs --can INTERFACE");
  Endpoint listen;
  try {
    listen = parseEndpoint(o.listen);
  } catch (const NetworkError& e) {
    throw ConfigError(std::string("--listen: ") + e.what());
  }
  if (!o.multicastGroup.empty() && !isMulticastGroup(o.multicastGroup))
    throw ConfigError("--multicast: expected an IPv4 multicast address (224.0.0.0 to 239.255.255.255), got \"" +
                      o.multicastGroup + "\"");
  // The outputs before the socket: a bad path is a usage error (exit 2) and opens nothing.
  if (!o.out.empty()) render::checkOutputPath(o.out);
  if (!o.canOut.empty()) render::checkOutputPath(o.canOut);
  render::checkDistinctOutputs({{"--out", o.out}, {"--can-out", o.canOut}});
  std::unique_ptr<UdpSocket> udp;
  std::unique_ptr<PcapRecorder> pcap;
  if (!o.out.empty()) {
    udp = std::make_unique<UdpSocket>(listen, o.multicastGroup.empty() ? std::nullopt : std::optional(o.multicastGroup));
    pcap = std::make_unique<PcapRecorder>(o.out, udp->localEndpoint());
  }
  int canFd = -1;
  std::unique_ptr<CandumpRecorder> candump;
  if (!o.canOut.empty()) {
    canFd = openSocketCan(o.canInterface);
    candump = std::make_unique<CandumpRecorder>(o.canOut, o.canInterface);
  }
  std::fprintf(stderr, "recording%s%s; Ctrl-C stops\n", udp ? (" UDP " + udp->localEndpoint().toString() + " to " + o.out).c_str() : "",
               candump ? (" CAN " + o.canInterface + " to " + o.canOut).c_str() : "");
  const auto start = std::chrono::steady_clock::now();
  std::array<std::uint8_t, 65536> buffer{};
  std::uint64_t datagrams = 0, frames = 0;
  auto unixNs = [] {
    return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  };
  while (!signals.requested()) {
    if (o.durationS > 0.0 && std::chrono::steady_clock::now() - start > std::chrono::duration<double>(o.durationS)) break;
    if (o.count > 0 && datagrams + frames >= o.count) break;
    if (udp) {
      sockaddr_in from{};
      const std::size_t n = udp->receive(buffer, from, std::chrono::milliseconds(canFd >= 0 ? 5 : 50));
      if (n > 0) {
        if (!pcap->record(std::span(buffer.data(), n), toSender(from), unixNs())) {
          std::fprintf(stderr, "skyig: recording stopped: %s\n", pcap->error().c_str());
          return 3;  // an I/O error (a full disk): what was recorded before it stays
        }
        ++datagrams;
      }
    }
    if (canFd >= 0) {
      pollfd p{canFd, POLLIN, 0};
      if (::poll(&p, 1, udp ? 0 : 50) > 0) {
        protocol::canaerospace::CanFrame f;
        if (::read(canFd, &f, sizeof f) == static_cast<ssize_t>(sizeof f)) {
          if (!candump->record(f, unixNs())) {
            std::fprintf(stderr, "skyig: recording stopped: %s\n", candump->error().c_str());
            return 3;
          }
          ++frames;
        }
      }
    }
  }
  if (canFd >= 0) ::close(canFd);
  std::printf("recorded %llu datagrams and %llu CAN frames\n", static_cast<unsigned long long>(datagrams),
              static_cast<unsigned long long>(frames));
  return 0;
}

struct ReplayCli {
  std::string configPath;
  std::string size;
  bool exr = false, png = false, quiet = false;
  std::string sendTo;
  ReplayOptions options;
};

int runReplay(ReplayCli& cli) {
  const StopOnSignal signals;  // the first SIGINT/SIGTERM ends the replay after its frame, with the summary
  ReplayOptions& o = cli.options;
  o.stop = &signals.flag();
  o.config = cli.configPath.empty() ? NodeConfig{} : loadNodeConfig(cli.configPath);
  if (!cli.size.empty())
    for (auto& c : o.config.channels) parseSize(cli.size, c.width, c.height);
  if (cli.exr || cli.png) o.writeExr = cli.exr, o.writePng = cli.png;
  if (!cli.sendTo.empty()) {
    try {
      o.sendTo = parseEndpoint(cli.sendTo);
    } catch (const NetworkError& e) {
      throw ConfigError(std::string("--send: ") + e.what());
    }
    // Port 0 is no one's: every datagram would be lost while the summary reported success.
    if (o.sendTo->port == 0) throw ConfigError("--send: port 0 is not a destination (give the IG's ADDR:PORT, e.g. 127.0.0.1:8004)");
  }
  o.progress = !cli.quiet;
  ReplayResult r;
  try {
    if (!o.sendTo) loadSkyData(o.config, o.stop);  // --send renders nothing: no tables, no catalogue
    r = replay(o);
  } catch (const atmosphere::Cancelled&) {
    r.stopped = true;  // signalled while the tables were being built: nothing replayed
  }
  std::printf("replayed %llu host messages%s: %llu frames (%llu drawn), %llu images in %.2f s (%.1f frames/s)%s\n",
              static_cast<unsigned long long>(r.events), o.sendTo ? (" to " + o.sendTo->toString()).c_str() : "",
              static_cast<unsigned long long>(r.frames), static_cast<unsigned long long>(r.framesDrawn),
              static_cast<unsigned long long>(r.imagesWritten), r.wallSeconds,
              r.wallSeconds > 0 ? static_cast<double>(r.frames) / r.wallSeconds : 0.0,
              r.skippedRecords ? (", skipped " + std::to_string(r.skippedRecords) + " bad records").c_str() : "");
  if (r.stopped) std::printf("stopped by a signal before the end of the recording\n");
  if (r.skippedGaps)
    std::printf("skipped %llu pauses longer than --max-gap %g s (%.3f s of recording time not rendered)\n",
                static_cast<unsigned long long>(r.skippedGaps), o.maxGapS, r.skippedGapSeconds);
  return 0;
}

}  // namespace

void registerRecordCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<RecordOptions>();
  CLI::App* c = app.add_subcommand("record", "Record what the host sends, unchanged: UDP to pcap, CAN to a candump log");
  c->add_option("--listen", o->listen, "UDP address ADDR:PORT to capture (0.0.0.0:8004)");
  c->add_option("--multicast", o->multicastGroup, "Join this multicast group");
  c->add_option("--out", o->out, "pcap file for the UDP datagrams");
  c->add_option("--can", o->canInterface, "SocketCAN interface to capture");
  c->add_option("--can-out", o->canOut, "candump log for the CAN frames");
  c->add_option("--duration", o->durationS, "Stop after this many seconds")->check(CLI::Range(0.0, 1e7));
  c->add_option("--count", o->count, "Stop after this many datagrams and frames");
  c->callback([o, &exitCode] { exitCode = runRecord(*o); });
}

void registerReplayCommand(CLI::App& app, int& exitCode) {
  auto cli = std::make_shared<ReplayCli>();
  ReplayOptions& o = cli->options;
  CLI::App* c = app.add_subcommand("replay", "Re-render a recorded host stream (pcap, pcapng, candump), or re-send it");
  c->add_option("recording", o.recording, "The recording")->required()->check(CLI::ExistingFile);
  c->add_option("--config", cli->configPath, "Node configuration (TOML)")->check(CLI::ExistingFile);
  c->add_flag("--realtime", o.realtime, "Pace frames as recorded (default: as fast as possible)");
  c->add_option("--frame-rate", o.frameRateHz, "IG frames per second of recording time (30)")->check(CLI::Range(0.1, 1000.0));
  c->add_option("--out", o.outDir, "Write frames to this directory, named by frame number and sim time");
  c->add_option("--every", o.every, "Write every Nth frame (1)")->check(CLI::Range(1, 1000000));
  c->add_flag("--exr", cli->exr, "Write EXR (default: EXR and PNG)");
  c->add_flag("--png", cli->png, "Write PNG (default: EXR and PNG)");
  c->add_option("--channel", o.channel, "Render this channel (default: the first)");
  c->add_flag("--all-channels", o.allChannels, "Render every channel");
  c->add_option("--size", cli->size, "Override the channels' resolution, WIDTHxHEIGHT");
  c->add_option("--from", o.from, "Start at this frame number or sim time (UTC)");
  c->add_option("--to", o.to, "Stop after this frame number or sim time (UTC)");
  c->add_option("--dump-state", o.dumpStatePath, "One JSON line per frame, as serve --dump-state");
  c->add_option("--send", cli->sendTo, "Re-transmit the recording to a live IG at ADDR:PORT instead of rendering");
  c->add_option("--port", o.port, "Only datagrams to this UDP port (0: all)")->check(CLI::Range(0, 65535));
  c->add_flag("--skip-bad", o.skipBad, "Pass over bad records, counting them, instead of stopping");
  c->add_option("--max-gap", o.maxGapS, "Skip pauses between records longer than this many seconds (60; 0: render them)")
      ->check(CLI::Range(0.0, 1e9));
  c->add_flag("--quiet", cli->quiet, "No progress bar");
  c->callback([cli, &exitCode] { exitCode = runReplay(*cli); });
}

}  // namespace skyig::services
