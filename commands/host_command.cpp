#include "commands/host_command.h"

#include "protocol/cigi/date.h"
#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "node/host/host_path.h"
#include "node/host/host_weather.h"
#include "node/config/node_config.h"
#include "node/transport/udp_socket.h"
#include "physics/weather/cloud_layer.h"

#include <cmath>
#include <algorithm>
#include <array>
#include <optional>
#include <cstdio>
#include <memory>
#include <vector>

namespace skyig::services {

namespace {

namespace cigi = protocol::cigi;

struct HostOptions {
  std::string pathFile;
  std::string to = "127.0.0.1:8004";
  std::string bind = "0.0.0.0:0";
  std::string multicastInterface;  // with a multicast --to: the interface's address (IP_MULTICAST_IF)
  int multicastTtl = 1;            // 1: the local network; 0: this machine only (tests)
  double rateHz = 30.0;
  std::string startUtc = "2026-06-21T19:00:00Z";
  double speed = 1.0;
  double durationS = 0.0;
  double visibilityM = 40000.0;
  std::optional<double> fogVisibilityM;  // a ground fog (Weather Control layer 0); 0: none
  double fogTopM = 200.0;
  double fogTransitionM = 0.0;  // its top's transition band
  std::optional<std::string> precipitation;  // Weather Control layers 4-9: a kind or "none"
  int precipitationSeverity = 2;
  std::string weatherFile;      // a weather script (node/host/host_weather.h) instead of the above
  std::string cloudSpec;        // --cloud: Weather Control layer 1 every frame, TYPE:BASE:THICKNESS[:COVERAGE[:WIND:FROM]]
  std::optional<sky::CloudLayer> cloud;  // cloudSpec parsed by run()
  // Weather Control only when asked for (a script, a fog or precipitation): without it the node
  // keeps the fog and precipitation of its own configuration.
  bool sendsWeather() const { return !weatherFile.empty() || fogVisibilityM.has_value() || precipitation.has_value(); }
  int dropEvery = 0;
  bool swapPairs = false;
  bool loop = false;
  bool littleEndian = false;
  int cigiVersion = 3;  // 3: CIGI 3.3; 4: CIGI 4.0
  int lockstep = 0;     // > 0: frame k+1 waits for this many Start of Frames naming frame k
  double lockstepTimeoutS = 1.0;
};

// Adds seconds to a UTC instant across days (time-lapse runs may pass midnight).
ephemeris::UtcTime advance(const ephemeris::UtcTime& t, double seconds) {
  ephemeris::UtcTime u = t;
  u.secondsOfDay += seconds;
  while (u.secondsOfDay >= 86400.0) {
    u.secondsOfDay -= 86400.0;
    static constexpr int kDays[12] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (u.year % 4 == 0 && u.year % 100 != 0) || u.year % 400 == 0;
    if (++u.day > kDays[u.month - 1] + (u.month == 2 && leap ? 1 : 0)) {
      u.day = 1;
      if (++u.month > 12) u.month = 1, ++u.year;
    }
  }
  return u;
}

// Cloud layer 1 as Weather Control sends it (global scope, the base above the model's ground).
cigi::WeatherControl cloudLayerPacket(const sky::CloudLayer& l) {
  cigi::WeatherControl w;
  w.layerId = 1;
  w.scope = cigi::WeatherScope::global;
  w.weatherEnable = l.enabled;
  w.cloudType = static_cast<std::uint8_t>(l.type);
  w.baseElevationM = static_cast<float>(l.baseM);
  w.thicknessM = static_cast<float>(l.thicknessM);
  w.coveragePct = static_cast<float>(l.coveragePct);
  w.severity = static_cast<std::uint8_t>(l.severity);
  w.horizontalWindSpeedMps = static_cast<float>(l.windSpeedMps);
  w.windDirectionDeg = static_cast<float>(l.windFromDeg);  // CIGI: the direction it blows from
  return w;
}

std::vector<std::uint8_t> message(std::uint32_t frame, double pathTime, const HostPath& path, const ephemeris::UtcTime& utc,
                                  double simElapsed, const WeatherStep& weather, const HostOptions& o) {
  cigi::IgControl ig;
  ig.hostFrameNumber = frame;
  ig.timestamp = static_cast<std::uint32_t>(std::llround(simElapsed * 1e5));  // the sim clock, 10 us ticks
  ig.timestampValid = true;
  const sky::Ownship p = path.at(pathTime);
  cigi::EntityControl e;
  e.entityId = 0;
  e.latitudeDeg = p.latitudeDeg;
  e.longitudeDeg = p.longitudeDeg;
  e.altitudeM = p.heightM;
  e.yawDeg = static_cast<float>(p.attitude.yawDeg);
  e.pitchDeg = static_cast<float>(p.attitude.pitchDeg);
  e.rollDeg = static_cast<float>(p.attitude.rollDeg);
  const OwnshipRates r = path.ratesAt(pathTime);
  cigi::RateControl rc;
  rc.xRateMps = static_cast<float>(r.x);
  rc.yRateMps = static_cast<float>(r.y);
  rc.zRateMps = static_cast<float>(r.z);
  rc.rollRateDegps = static_cast<float>(r.rollRate);
  rc.pitchRateDegps = static_cast<float>(r.pitchRate);
  rc.yawRateDegps = static_cast<float>(r.yawRate);
  cigi::CelestialSphereControl cs;
  cs.date = *cigi::composeDate({utc.year, utc.month, utc.day});
  cs.hour = static_cast<std::uint8_t>(utc.secondsOfDay / 3600.0);
  cs.minute = static_cast<std::uint8_t>(std::fmod(utc.secondsOfDay, 3600.0) / 60.0);
  cs.seconds = static_cast<float>(std::fmod(utc.secondsOfDay, 60.0));  // sent by CIGI 4.0 only
  cigi::AtmosphereControl a;
  a.visibilityRangeM = static_cast<float>(weather.visibilityM);
  a.globalHumidityPct = static_cast<std::uint8_t>(std::lround(weather.humidityPct));
  // The ground fog, every frame while the weather is scripted (a node that joins late sees it):
  // layer 0, global scope.
  cigi::WeatherControl fog;
  fog.layerId = 0;
  fog.scope = cigi::WeatherScope::global;
  fog.weatherEnable = weather.fogVisibilityM > 0.0;
  fog.visibilityRangeM = static_cast<float>(weather.fogVisibilityM);
  fog.baseElevationM = 0.0f;
  fog.thicknessM = static_cast<float>(weather.fogTopM);
  fog.transitionBandM = static_cast<float>(o.fogTransitionM);
  fog.humidityPct = 100;
  // skyig's CIGI 4.0 subset has no Rate Control (4.0 moved rates to Velocity Control).
  std::vector<cigi::Packet> packets = {ig, e};
  if (o.cigiVersion != 4) packets.push_back(rc);
  packets.push_back(cs);
  packets.push_back(a);
  if (o.sendsWeather()) {
    packets.push_back(fog);
    // Every precipitation layer, the step's on and the others off, from the ground up.
    for (std::size_t k = 0; k < weather::kPrecipitationKinds; ++k) {
      cigi::WeatherControl layer;
      layer.layerId = static_cast<std::uint8_t>(weather::kFirstPrecipitationLayerId + k);
      layer.scope = cigi::WeatherScope::global;
      layer.weatherEnable = weather.precipitation && static_cast<std::size_t>(*weather.precipitation) == k;
      layer.severity = static_cast<std::uint8_t>(weather.precipitationSeverity);
      layer.visibilityRangeM = static_cast<float>(weather.precipitationVisibilityM);
      layer.coveragePct = 100.0f;
      layer.thicknessM = static_cast<float>(weather.precipitationTopM);
      packets.push_back(layer);
    }
  }
  // Cloud layer 1: the script's step where the script has clouds (off where it says none), else --cloud.
  if (weather.cloud) packets.push_back(cloudLayerPacket(*weather.cloud));
  const auto order = o.littleEndian ? protocol::ByteOrder::little : protocol::ByteOrder::big;
  std::vector<std::uint8_t> bytes;
  const std::string error = o.cigiVersion == 4 ? cigi::encodeMessage4(packets, order, bytes)
                                               : cigi::encodeMessage(packets, order, bytes);
  if (!error.empty()) throw std::runtime_error("encoding host message: " + error);
  return bytes;
}

// The Start of Frame messages the IG sends back to the host's socket.
struct StartOfFrameLog {
  std::uint64_t received = 0;
  std::uint64_t other = 0;  // datagrams that are not a well-formed Start of Frame message
  std::vector<std::uint8_t> lastBytes;
  cigi::DecodedMessage last;

  void add(std::span<const std::uint8_t> bytes) {
    cigi::DecodedMessage m = cigi::decodeMessage(bytes);
    if (!m.ok() || m.packets.empty() || !std::holds_alternative<cigi::StartOfFrame>(m.packets.front())) {
      ++other;
      return;
    }
    ++received;
    lastBytes.assign(bytes.begin(), bytes.end());
    last = std::move(m);
  }

  // Receives until `until`, so the host reads the IG's answers while it waits for its next frame;
  // with `answers`, returns early once that many Start of Frames named `frame` (synchronous
  // nodes answer each host frame they show). Returns whether they did.
  bool receiveUntil(UdpSocket& socket, std::chrono::steady_clock::time_point until, std::uint32_t frame = 0,
                    int answers = 0) {
    std::array<std::uint8_t, 2048> buffer{};
    sockaddr_in from{};
    int answered = 0;
    for (;;) {
      const auto now = std::chrono::steady_clock::now();
      const auto left = std::chrono::ceil<std::chrono::milliseconds>(until - now);
      const std::size_t n = socket.receive(buffer, from, std::max(left, std::chrono::milliseconds(0)));
      if (n > 0) {
        const std::uint64_t before = received;
        add(std::span(buffer.data(), n));
        if (answers > 0 && received > before &&
            std::get<cigi::StartOfFrame>(last.packets.front()).lastHostFrameNumber == frame && ++answered >= answers)
          return true;
      } else if (std::chrono::steady_clock::now() >= until) {
        return answers == 0;
      }
    }
  }

  void print() const {
    if (received == 0 && other == 0) return;
    std::printf("host: %llu Start of Frame received, %llu other datagrams\n", static_cast<unsigned long long>(received),
                static_cast<unsigned long long>(other));
    if (received == 0) return;
    const auto& s = std::get<cigi::StartOfFrame>(last.packets.front());
    std::printf("host: last Start of Frame: CIGI %u.%u, IG frame %u, last host frame %u, timestamp %u\n",
                static_cast<unsigned>(last.majorVersion), static_cast<unsigned>(last.minorVersion), s.igFrameNumber,
                s.lastHostFrameNumber, s.timestamp);
    std::string hex;
    for (std::uint8_t b : lastBytes) {
      char buf[4];
      std::snprintf(buf, sizeof buf, "%s%02X", hex.empty() ? "" : " ", b);
      hex += buf;
    }
    std::printf("host: last Start of Frame bytes: %s\n", hex.c_str());
  }
};

int run(HostOptions o) {
  const HostPath path = HostPath::load(o.pathFile);
  if (!o.cloudSpec.empty()) {
    try {
      o.cloud = weather::parseCloudSpec(o.cloudSpec);
    } catch (const std::invalid_argument& e) {
      throw ConfigError(std::string("--cloud: ") + e.what());
    }
  }
  WeatherStep constant;
  constant.visibilityM = o.visibilityM;
  constant.fogVisibilityM = o.fogVisibilityM.value_or(0.0);
  constant.fogTopM = o.fogTopM;
  constant.cloud = o.cloud;
  if (o.precipitation) {
    constant.precipitation = weather::parsePrecipitation(*o.precipitation);  // "none": none
    constant.precipitationSeverity = o.precipitationSeverity;
  }
  const HostWeather weather = o.weatherFile.empty() ? HostWeather::constant(constant) : HostWeather::load(o.weatherFile);
  const auto start = ephemeris::parseIso8601Utc(o.startUtc);
  if (!start) throw ConfigError("--start-utc: expected a UTC time like 2026-06-21T19:00:00Z, got \"" + o.startUtc + "\"");
  Endpoint to, local;
  try {
    to = parseEndpoint(o.to);
    local = parseEndpoint(o.bind);
  } catch (const NetworkError& e) {
    throw ConfigError(std::string("--to/--bind: ") + e.what());
  }
  UdpSocket socket(local);
  const bool multicast = isMulticastGroup(to.address);
  if (!multicast && !o.multicastInterface.empty())
    throw ConfigError("--multicast-interface: --to " + to.toString() + " is not a multicast group (224.0.0.0/4)");
  if (multicast) {
    // One datagram per frame reaches every node of the dome; looped back so nodes on this
    // machine hear it too.
    try {
      socket.sendMulticastThrough(o.multicastInterface.empty() ? local.address : o.multicastInterface, o.multicastTtl);
    } catch (const NetworkError& e) {
      throw ConfigError(std::string("--multicast-interface/--multicast-ttl: ") + e.what());
    }
  }
  const sockaddr_in destination = toSockaddr(to);
  const double duration = o.durationS > 0.0 ? o.durationS : path.durationS();
  const auto frames = static_cast<std::uint32_t>(std::floor(duration * o.rateHz)) + 1;
  const auto period = std::chrono::duration<double>(1.0 / o.rateHz);
  const auto t0 = std::chrono::steady_clock::now();
  std::uint64_t sent = 0, dropped = 0, unanswered = 0;
  std::vector<std::uint8_t> held;  // --swap-pairs: the even frame waits for the odd one
  StartOfFrameLog sof;
  for (std::uint32_t k = 0; k < frames; ++k) {
    sof.receiveUntil(socket, t0 + std::chrono::duration_cast<std::chrono::steady_clock::duration>(period * k));
    // Path time from the frame number, not the wall clock: the flight is reproducible.
    const double t = k / o.rateHz;
    const double pathTime = o.loop ? std::fmod(t, path.durationS()) : t;
    const std::vector<std::uint8_t> bytes =
        message(k, pathTime, path, advance(*start, t * o.speed), t * o.speed, weather.at(t), o);
    if (o.dropEvery > 0 && (k + 1) % static_cast<std::uint32_t>(o.dropEvery) == 0) {
      ++dropped;
      continue;
    }
    if (o.swapPairs && held.empty() && k + 1 < frames) {
      held = bytes;
      continue;
    }
    sent += socket.sendTo(bytes, destination);
    if (!held.empty()) {
      sent += socket.sendTo(held, destination);
      held.clear();
    }
    // Lock step: the next frame waits until every node showed this one (each answers with a
    // Start of Frame naming it), or the timeout; --rate stays the fastest pace.
    if (o.lockstep > 0 &&
        !sof.receiveUntil(socket,
                          std::chrono::steady_clock::now() +
                              std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                  std::chrono::duration<double>(o.lockstepTimeoutS)),
                          k, o.lockstep))
      ++unanswered;
  }
  std::printf("host: %u frames over %.1f s to %s: %llu sent, %llu dropped%s\n", frames, duration, to.toString().c_str(),
              static_cast<unsigned long long>(sent), static_cast<unsigned long long>(dropped),
              o.swapPairs ? ", pairs swapped" : "");
  if (o.lockstep > 0)
    std::printf("host: lock step with %d node(s): %llu frame(s) not answered by all within %.3f s\n", o.lockstep,
                static_cast<unsigned long long>(unanswered), o.lockstepTimeoutS);
  sof.print();
  return 0;
}

}  // namespace

void registerHostCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<HostOptions>();
  CLI::App* c = app.add_subcommand("host", "Host emulator: fly a scripted path and send CIGI over UDP");
  c->add_option("--path", o->pathFile, "Waypoints CSV: time_s, lat, lon, alt_m, yaw, pitch, roll (e.g. config/circuit.csv)")
      ->required()
      ->check(CLI::ExistingFile);
  c->add_option("--to", o->to, "IG address ADDR:PORT, or a multicast group GROUP:PORT every node joins (127.0.0.1:8004)");
  c->add_option("--bind", o->bind, "Local address ADDR:PORT to send from (0.0.0.0:0)");
  c->add_option("--multicast-interface", o->multicastInterface,
                "With a multicast --to: the IPv4 address of the interface to send through (default: --bind's address)");
  c->add_option("--multicast-ttl", o->multicastTtl,
                "With a multicast --to: time-to-live, 0 keeps datagrams on this machine (1)")
      ->check(CLI::Range(0, 255));
  c->add_option("--rate", o->rateHz, "Host frame rate, Hz (30)")->check(CLI::Range(1.0, 1000.0));
  c->add_option("--start-utc", o->startUtc, "UTC date and time at the start of the path (2026-06-21T19:00:00Z)");
  c->add_option("--speed", o->speed, "Time-lapse: sim seconds of the clock per second flown (1)")->check(CLI::Range(0.0, 1e5));
  c->add_option("--duration", o->durationS, "Seconds to fly (default: the path's length)")->check(CLI::Range(0.0, 1e7));
  c->add_option("--visibility", o->visibilityM, "Atmosphere Control visibility, m (40000)")->check(CLI::Range(0.0, 1e6));
  c->add_option("--fog-visibility", o->fogVisibilityM, "Weather Control layer 0 (ground fog): visibility inside, m (0: none)")
      ->check(CLI::Range(0.0, 1e6));
  c->add_option("--fog-top", o->fogTopM, "The ground fog's thickness above the ground, m (200)")->check(CLI::Range(1.0, 20000.0));
  c->add_option("--fog-transition", o->fogTransitionM, "Its transition band: the top fades to clear air over it, m (0)")
      ->check(CLI::Range(0.0, 20000.0));
  c->add_option("--precipitation", o->precipitation,
                "Weather Control layers 4-9: none | rain | snow | sleet | hail | sand | dust, from the ground to 1500 m")
      ->check(CLI::IsMember({"none", "rain", "snow", "sleet", "hail", "sand", "dust"}));
  c->add_option("--precipitation-severity", o->precipitationSeverity, "Its severity, 0 (least) .. 5; its visibility follows (2)")
      ->check(CLI::Range(0, 5));
  c->add_option("--weather", o->weatherFile,
                "Weather script CSV: time_s, visibility_m, humidity_pct, fog_visibility_m, fog_top_m [, precipitation, "
                "severity, precipitation_visibility_m, precipitation_top_m [, cloud]], each held until the next (e.g. "
                "config/fog_lifting.csv, config/showers.csv, config/ceiling_lowering.csv); replaces --visibility, "
                "--fog-* and --precipitation* (and --cloud where it has the cloud column)")
      ->check(CLI::ExistingFile);
  c->add_option("--cloud", o->cloudSpec,
                "Weather Control layer 1 every frame: TYPE:BASE:THICKNESS[:COVERAGE[:WIND:FROM]] (m, %, m/s, degrees it "
                "blows from), e.g. stratus:300:400:100 or cumulus:1200:800:50:10:270; a --weather script with a "
                "cloud column replaces it");
  c->add_option("--drop-every", o->dropEvery, "Drop every Nth datagram (loss test)")->check(CLI::Range(0, 1000000));
  c->add_flag("--swap-pairs", o->swapPairs, "Send datagrams in swapped pairs (reordering test)");
  c->add_flag("--loop", o->loop, "Fly the path round and round for --duration");
  c->add_flag("--little-endian", o->littleEndian, "Send in little-endian byte order (the magic number says so)");
  c->add_option("--lockstep", o->lockstep,
                "Synchronous host: send frame k+1 only after N Start of Frames named frame k (N nodes in "
                "synchronous mode replying to --bind), or --lockstep-timeout; --rate stays the fastest pace (0: off)")
      ->check(CLI::Range(0, 1000));
  c->add_option("--lockstep-timeout", o->lockstepTimeoutS, "Seconds a lock-step frame waits for its answers (1)")
      ->check(CLI::Range(0.001, 60.0));
  c->add_option("--cigi", o->cigiVersion,
                "CIGI version to send: 3 (3.3) or 4 (4.0: IG Control, Entity Position Control, Celestial Sphere "
                "Control with seconds, Atmosphere Control) (3)")
      ->check(CLI::IsMember({3, 4}));
  c->callback([o, &exitCode] { exitCode = run(*o); });
}

}  // namespace skyig::services
