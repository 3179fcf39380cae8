#include "commands/serve_command.h"

#include "render/image_io.h"
#include "render/output_file.h"
#include "node/node.h"
#include "node/config/sky_data.h"
#include "node/frame/state_dump.h"
#include "node/common/stop_signal.h"
#include "physics/atmosphere/precompute/precompute_control.h"

#include <spdlog/spdlog.h>

#include <memory>

namespace skyig::services {

namespace {

struct ServeOptions {
  std::string configPath;
  std::string node;
  bool headless = false;
  std::string listen, replyTo, multicastInterface, dumpState, statsJson, canInterface, record, saveFrames;
  std::uint64_t saveEvery = 30;
  std::uint64_t frames = 0;
  bool synchronous = false;
  double frameRate = 0.0;
  double logIntervalS = 5.0;
};

int run(const ServeOptions& o) {
  const StopOnSignal signals;  // from the start: a node stopped while its tables build exits 0
  NodeOptions opt;
  opt.config = o.configPath.empty() ? NodeConfig{} : loadNodeConfig(o.configPath);
  if (!o.node.empty()) opt.config.nodeName = o.node;
  spdlog::info("configuration: {}", o.configPath.empty() ? std::string("the built-in defaults") : o.configPath);
  const HostLink& h = opt.config.host;
  try {
    opt.listen = parseEndpoint(o.listen.empty() ? h.listen : o.listen);
    if (!o.replyTo.empty()) opt.replyTo = parseEndpoint(o.replyTo);
    else if (!h.replyTo.empty())
      opt.replyTo = parseEndpoint(h.replyTo);  // checked when the file was read
  } catch (const NetworkError& e) {
    throw ConfigError(std::string(o.listen.empty() && o.replyTo.empty() ? "host.listen: " : "--listen/--reply-to: ") + e.what());
  }
  if (!h.multicastGroup.empty()) opt.multicastGroup = h.multicastGroup;
  const std::string interface = o.multicastInterface.empty() ? h.multicastInterface : o.multicastInterface;
  if (!o.multicastInterface.empty() && (h.multicastGroup.empty() || !isIpv4Address(interface)))
    throw ConfigError("--multicast-interface: expected the IPv4 address of an interface, with host.multicast_group set; got \"" +
                      interface + "\"" + (h.multicastGroup.empty() ? " and no multicast_group" : ""));
  if (!interface.empty()) opt.multicastInterface = interface;
  opt.replyPort = static_cast<std::uint16_t>(h.replyPort);
  opt.synchronous = o.synchronous || h.synchronous;
  opt.syncTimeoutS = h.syncTimeoutS;
  opt.frameRateHz = o.frameRate > 0.0 ? o.frameRate : h.frameRateHz;
  opt.headless = o.headless;
  opt.frames = o.frames;
  opt.dumpStatePath = o.dumpState;
  opt.statsPath = o.statsJson;
  opt.recordPath = o.record;
  opt.saveFramesDir = o.saveFrames;
  opt.saveEvery = o.saveEvery;
  opt.logIntervalS = o.logIntervalS;
  // Output files are checked before anything starts: a bad path is a usage error (exit 2).
  for (const std::string* path : {&o.dumpState, &o.statsJson, &o.record})
    if (!path->empty()) render::checkWritable(*path);
  render::checkDistinctOutputs({{"--dump-state", o.dumpState}, {"--stats-json", o.statsJson}, {"--record", o.record}});
  const std::string can = o.canInterface.empty() ? h.canInterface : o.canInterface;
  if (!can.empty()) opt.canInterface = can;

  NodeStats stats;
  int code = 0;
  try {
    loadSkyData(opt.config, &signals.flag());
    code = runNode(opt, stats, signals.flag());
  } catch (const atmosphere::Cancelled&) {
    // Signalled while the tables were being built: nothing was served, which the stats say.
    if (!opt.statsPath.empty()) writeStatsFile(opt.statsPath, stats);
  }
  spdlog::info("stopped{} after {} frames; {} datagrams, {} malformed", signals.requested() ? " by a signal" : "",
               stats.frames.load(), stats.datagrams.load(), stats.malformedDatagrams.load());
  return code;
}

}  // namespace

void registerServeCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<ServeOptions>();
  CLI::App* c = app.add_subcommand("serve", "Run the IG node: the host's state in, every channel of this node out");
  c->add_option("--config", o->configPath, "Node configuration (TOML)")->check(CLI::ExistingFile);
  c->add_option("--node", o->node, "This node's name: renders the channels assigned to it (default: [node] name)");
  c->add_flag("--headless", o->headless, "Render offscreen through EGL instead of windows");
  c->add_option("--listen", o->listen, "Host-to-IG address ADDR:PORT (default: host.listen, 0.0.0.0:8004)");
  c->add_option("--reply-to", o->replyTo,
                "Where Start of Frame goes, ADDR:PORT (default: host.reply_to, else the followed host's address, port "
                "host.reply_port)");
  c->add_option("--multicast-interface", o->multicastInterface,
                "IPv4 address of the interface host.multicast_group is joined on: per machine, where one "
                "configuration serves every node (default: host.multicast_interface, else the listen address)");
  c->add_option("--can", o->canInterface, "Also read CANaerospace from this SocketCAN interface, e.g. can0");
  c->add_option("--frames", o->frames, "Stop after N frames (default: run until SIGINT/SIGTERM)");
  c->add_flag("--sync", o->synchronous, "Synchronous mode: render frame N after the host's frame N (with a timeout)");
  c->add_option("--frame-rate", o->frameRate, "Headless frame rate, Hz (default: host.frame_rate, 60)")->check(CLI::Range(1.0, 1000.0));
  c->add_option("--dump-state", o->dumpState, "Write one JSON line per frame: host values, values used, sun");
  c->add_option("--record", o->record, "Record every datagram received to this pcap file while serving");
  c->add_option("--save-frames", o->saveFrames,
                "Write every channel's frame (EXR in cd/m^2, PNG as displayed) to this directory, as replay names them");
  c->add_option("--save-every", o->saveEvery, "With --save-frames: every Nth frame (30)")->check(CLI::PositiveNumber);
  c->add_option("--stats-json", o->statsJson, "Write counters and latency percentiles every few seconds and on exit");
  c->add_option("--log-interval", o->logIntervalS,
                "Seconds between the frame-timing info lines (frame rate, frame and channel times, frames over the "
                "period, host frame age; default 5, 0: only the summary at exit)")
      ->check(CLI::Range(0.0, 3600.0));
  c->callback([o, &exitCode] { exitCode = run(*o); });
}

}  // namespace skyig::services
