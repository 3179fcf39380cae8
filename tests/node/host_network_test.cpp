// The host link on real loopback sockets: the CIGI receiver thread fed by hosts that restart,
// strangers and spoofers (127.0.0.2 is another address on loopback), a host whose datagrams
// come in bursts of two, a host switching a channel's goggle with Sensor Control, and
// `skyig serve` processes competing for a port.
#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "node/transport/cigi_receiver.h"
#include "node/frame/sky_worker.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>

#include <functional>

#include <arpa/inet.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

using namespace skyig::services;
using namespace skyig::services::testing;
namespace cigi = skyig::protocol::cigi;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

// The receiver thread of a node on its own loopback port.
class Receiver {
 public:
  explicit Receiver(HostSessionSettings settings = {})
      : socket_({"127.0.0.1", 0}), cigi_(stats, latest, std::move(settings)) {
    thread_ = std::thread([this] { cigi_.run(socket_, stop_); });
  }
  ~Receiver() {
    stop_ = true;
    thread_.join();
  }
  sockaddr_in address() const { return toSockaddr(socket_.localEndpoint()); }
  // Waits until the receiver has handled `n` datagrams in all, each to its end: published, or
  // counted as dropped.
  bool handled(std::uint64_t n) {
    return waitUntil([&] {
      return latest.version() + stats.staleMessages.load() + stats.notAllowedDatagrams.load() +
                 stats.otherHostDatagrams.load() + stats.malformedDatagrams.load() + stats.notHostMessages.load() >=
             n;
    });
  }

  NodeStats stats;
  Latest<HostSnapshot> latest;

 private:
  UdpSocket socket_;
  CigiReceiver cigi_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// One host frame: IG Control and the ownship.
void sendFrame(UdpSocket& host, const sockaddr_in& to, std::uint32_t frame, double latitude, double yaw = 0.0,
               std::optional<std::uint32_t> timestamp = std::nullopt) {
  cigi::IgControl ig;
  ig.hostFrameNumber = frame;
  ig.timestampValid = timestamp.has_value();
  ig.timestamp = timestamp.value_or(0);
  cigi::EntityControl e;
  e.latitudeDeg = latitude;
  e.longitudeDeg = 11.0;
  e.altitudeM = 1000.0;
  e.yawDeg = static_cast<float>(yaw);
  const cigi::Packet packets[] = {ig, e};
  std::vector<std::uint8_t> bytes;
  ASSERT_EQ(cigi::encodeMessage(packets, skyig::protocol::ByteOrder::big, bytes), "");
  ASSERT_TRUE(host.sendTo(bytes, to));
}

std::uint64_t sessionsStarted(const NodeStats& s) {
  std::uint64_t n = 0;
  for (const auto& c : s.sessions) n += c.load();
  return n;
}

}  // namespace

// After 600 frames a restarted host (a new process: another source port; or the same port
// again) counts from 0. Its first datagram is shown at once, none is dropped as stale.
TEST(HostNetwork, RestartedHostIsFollowedWithinOneHostFrame) {
  Receiver node;
  std::uint16_t port = 0;
  {
    UdpSocket host({"127.0.0.1", 0});
    port = host.localEndpoint().port;
    for (std::uint32_t n = 0; n < 600; ++n) {
      sendFrame(host, node.address(), n, 47.0);
      if (n % 100 == 99) {
        ASSERT_TRUE(node.handled(n + 1));  // paced by the receiver: nothing lost on loopback
      }
    }
  }
  ASSERT_TRUE(node.handled(600));
  ASSERT_EQ(node.latest.get()->state.hostFrame, 599u);
  const std::uint64_t published = node.latest.version();
  {
    UdpSocket restarted({"127.0.0.1", 0});  // a new process, a new port
    sendFrame(restarted, node.address(), 0, 48.0);
    ASSERT_TRUE(node.handled(601));
    EXPECT_EQ(node.latest.version(), published + 1);
    EXPECT_EQ(node.latest.get()->state.hostFrame, 0u);
    EXPECT_EQ(node.latest.get()->state.ownship.latitudeDeg, 48.0);
    EXPECT_EQ(node.stats.sessions[static_cast<std::size_t>(SessionReason::newPort)].load(), 1u);
    for (std::uint32_t n = 1; n < 100; ++n) sendFrame(restarted, node.address(), n, 48.0);
    ASSERT_TRUE(node.handled(700));
  }
  {
    UdpSocket samePort({"127.0.0.1", port});  // restarted on a fixed port: its counter starts again
    sendFrame(samePort, node.address(), 0, 49.0);
    ASSERT_TRUE(node.handled(701));
    EXPECT_EQ(node.latest.get()->state.ownship.latitudeDeg, 49.0);
  }
  EXPECT_EQ(node.stats.staleMessages.load(), 0u);
  EXPECT_EQ(sessionsStarted(node.stats), 3u);  // first, new port, new port again
}

// One datagram from another address with the frame number a host would reach in 2^31 - 1
// frames: the real host's next 90 frames are all shown, the stranger's never.
TEST(HostNetwork, PoisonedFrameNumberFromAnotherAddressChangesNothing) {
  Receiver node;
  UdpSocket host({"127.0.0.1", 0});
  UdpSocket stranger({"127.0.0.2", 0});
  for (std::uint32_t n = 1; n <= 100; ++n) sendFrame(host, node.address(), n, 47.0);
  ASSERT_TRUE(node.handled(100));
  sendFrame(stranger, node.address(), 100 + 0x7fffffffu, 10.0);
  ASSERT_TRUE(node.handled(101));
  for (std::uint32_t n = 101; n <= 190; ++n) sendFrame(host, node.address(), n, 47.0 + n * 1e-4);
  ASSERT_TRUE(node.handled(191));
  EXPECT_EQ(node.latest.version(), 190u);  // every frame of the host published, nothing else
  EXPECT_EQ(node.latest.get()->state.hostFrame, 190u);
  EXPECT_EQ(node.latest.get()->state.ownship.latitudeDeg, 47.0 + 190 * 1e-4);
  EXPECT_EQ(node.latest.get()->sender->address, 0x7F000001u);  // 127.0.0.1
  EXPECT_EQ(node.stats.staleMessages.load(), 0u);
  EXPECT_EQ(node.stats.otherHostDatagrams.load(), 1u);
  EXPECT_EQ(sessionsStarted(node.stats), 1u);
}

TEST(HostNetwork, SenderOutsideHostAllowedIsCountedAndIgnored) {
  HostSessionSettings settings;
  settings.allowed = {parseAddressRange("127.0.0.1/32")};
  Receiver node(settings);
  UdpSocket stranger({"127.0.0.2", 0});
  for (std::uint32_t n = 0; n < 10; ++n) sendFrame(stranger, node.address(), n, 10.0);
  ASSERT_TRUE(node.handled(10));
  EXPECT_EQ(node.stats.notAllowedDatagrams.load(), 10u);
  EXPECT_EQ(node.latest.version(), 0u);  // nothing reached the state
  UdpSocket host({"127.0.0.1", 0});
  sendFrame(host, node.address(), 0, 47.0);
  ASSERT_TRUE(node.handled(11));
  EXPECT_EQ(node.latest.version(), 1u);
  EXPECT_EQ(node.latest.get()->state.ownship.latitudeDeg, 47.0);
}

// A 30 Hz host turning 0.5 deg a frame (15 deg/s), one frame a second held up and sent with
// the next: the view predicted at any instant stays within a degree of the host's path.
TEST(HostNetwork, BurstsOfTwoDatagramsKeepThePredictedViewOnThePath) {
  Receiver node;
  UdpSocket host({"127.0.0.1", 0});
  const auto start = Clock::now() + 50ms;
  constexpr double kRate = 15.0;  // deg/s
  const auto pathAt = [&](Clock::time_point t) { return std::chrono::duration<double>(t - start).count() * kRate; };
  std::atomic<bool> done{false};
  std::thread sender([&] {
    std::optional<std::pair<std::uint32_t, Clock::time_point>> held;
    for (std::uint32_t k = 0; k < 120; ++k) {  // 4 s
      std::this_thread::sleep_until(start + std::chrono::microseconds(33333 * k));
      const auto now = Clock::now();
      auto send = [&](std::uint32_t n, Clock::time_point at) {
        const auto ticks = std::chrono::duration_cast<std::chrono::microseconds>(at - start).count() / 10 + 1'000'000;
        sendFrame(host, node.address(), n, 47.0, std::fmod(pathAt(at) + 3600.0, 360.0),
                  static_cast<std::uint32_t>(ticks));
      };
      if (k % 30 == 15) {  // held up: goes out with the next frame
        held = {k, now};
        continue;
      }
      if (held) send(held->first, held->second);
      held.reset();
      send(k, now);
    }
    done = true;
  });
  double worst = 0.0;
  int samples = 0;
  while (!done) {
    std::this_thread::sleep_for(2ms);
    const auto snapshot = node.latest.get();
    if (!snapshot || snapshot->state.hostFrame < 3) continue;
    const auto now = Clock::now();
    const double error = std::abs(wrap180(snapshot->predictor.at(now).attitude.yawDeg - pathAt(now)));
    worst = std::max(worst, error);
    ++samples;
  }
  sender.join();
  EXPECT_GT(samples, 500);
  EXPECT_LT(worst, 1.0) << "over " << samples << " samples";
  EXPECT_EQ(node.stats.staleMessages.load(), 0u);
}


// SO_REUSEADDR let a second node bind a unicast port and silently take the stream. Without it
// the second `serve` stops with exit code 4 and says the port is in use; the first goes on.
TEST(HostNetwork, SecondServeOnATakenPortExitsFour) {
  const fs::path dir = freshTestDirectory("skyig_host_network_");
  std::ofstream(dir / "node.toml")
      << "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\nwidth = 32\nheight = 24\n";
  const std::uint16_t port = freeLoopbackPort();
  const std::string serve = "serve --config " + (dir / "node.toml").string() +
                            " --headless --frame-rate 10 --listen 127.0.0.1:" + std::to_string(port);
  SkyigProcess first("--log-level info " + serve, dir / "first.log");
  ASSERT_TRUE(waitUntil([&] {
    return first.output().find("listening for CIGI") != std::string::npos || !first.running();
  })) << first.output();
  ASSERT_TRUE(first.running()) << first.output();
  const std::string command =
      std::string(SKYIG_EXECUTABLE) + " " + serve + " --frames 1 >/dev/null 2>" + (dir / "second.err").string();
  const int status = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 4);
  std::ifstream in(dir / "second.err");
  const std::string second((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(second.find("127.0.0.1:" + std::to_string(port) + ": the port is in use"), std::string::npos) << second;
  EXPECT_TRUE(first.running()) << first.output();
  EXPECT_EQ(first.stop(), 0);
  fs::remove_all(dir);
}

// Multicast keeps sharing: the nodes of a dome on one machine join the same group on the same
// port (and never send on it: multicast in tests stays on loopback with TTL 0; the group is
// joined on the loopback interface, so not even the membership report leaves the machine). A
// unicast bind of that port is still refused.
TEST(HostNetwork, MulticastGroupStillShared) {
  const std::uint16_t port = freeLoopbackPort();
  const std::string group = "239.255.42.99";
  const std::optional<std::string> loopback = "127.0.0.1";
  UdpSocket a({"0.0.0.0", port}, group, loopback);
  EXPECT_NO_THROW(UdpSocket({"0.0.0.0", port}, group, loopback));
  EXPECT_THROW(UdpSocket({"127.0.0.1", port}), NetworkError);
}

// A host sends each frame once to a multicast group and every node on the machine hears it:
// two members joined on the loopback interface, a sender through 127.0.0.1 with TTL 0 (the
// datagram never leaves the machine) and multicast loopback on.
TEST(HostNetwork, MulticastOnLoopbackReachesEveryMember) {
  const std::uint16_t port = freeLoopbackPort();
  const std::string group = "239.255.42.98";
  UdpSocket a({"0.0.0.0", port}, group, std::string("127.0.0.1"));
  UdpSocket b({"0.0.0.0", port}, group, std::string("127.0.0.1"));
  UdpSocket host({"127.0.0.1", 0});
  host.sendMulticastThrough("127.0.0.1", 0);
  const std::vector<std::uint8_t> bytes = {1, 2, 3, 4};
  ASSERT_TRUE(host.sendTo(bytes, toSockaddr({group, port})));
  for (UdpSocket* member : {&a, &b}) {
    std::array<std::uint8_t, 16> buffer{};
    sockaddr_in from{};
    ASSERT_EQ(member->receive(buffer, from, 2000ms), bytes.size());
    EXPECT_EQ(fromSockaddr(from).toString(), host.localEndpoint().toString());
  }
}

// A multicast interface that is not an address, or not this machine's, is refused by name.
TEST(HostNetwork, MulticastInterfaceIsNamedWhenRefused) {
  const std::uint16_t port = freeLoopbackPort();
  try {
    UdpSocket s({"0.0.0.0", port}, std::string("239.255.42.97"), std::string("127.0.0.300"));
    FAIL() << "joined on a bad interface address";
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("\"127.0.0.300\" is not an IPv4 address"), std::string::npos) << e.what();
  }
  try {
    UdpSocket s({"0.0.0.0", port}, std::string("239.255.42.97"), std::string("192.0.2.77"));  // TEST-NET-1
    FAIL() << "joined on an interface this machine does not have";
  } catch (const NetworkError& e) {
    EXPECT_NE(std::string(e.what()).find("on interface 192.0.2.77"), std::string::npos) << e.what();
  }
  UdpSocket host({"127.0.0.1", 0});
  EXPECT_THROW(host.sendMulticastThrough("127.0.0.1", 256), NetworkError);
}

namespace {

// A host message switching view `view`'s sensor (the channel's goggle).
void sendSensorControl(UdpSocket& host, const sockaddr_in& to, std::uint32_t frame, std::uint16_t view, bool on,
                       bool automaticGain, float gain) {
  cigi::IgControl ig;
  ig.hostFrameNumber = frame;
  cigi::SensorControl s;
  s.viewId = view;
  s.sensorId = 3;  // any id: skyig's one sensor per view is the goggle
  s.sensorOn = on;
  s.automaticGain = automaticGain;
  s.gain = gain;
  const cigi::Packet packets[] = {ig, s};
  std::vector<std::uint8_t> bytes;
  ASSERT_EQ(cigi::encodeMessage(packets, skyig::protocol::ByteOrder::big, bytes), "");
  ASSERT_TRUE(host.sendTo(bytes, to));
}

// Three channels: the eye's; a class B goggle that starts switched off, on automatic gain; a
// class A goggle switched on from the start.
NodeConfig goggleConfig() {
  return parseNodeConfig("[[channel]]\nname = \"front\"\n[[channel]]\nname = \"nvg\"\nyaw = 30\n"
                         "[channel.goggle]\nclass = \"B\"\nphosphor = \"P45\"\n"
                         "[[channel]]\nname = \"nvg-on\"\n[channel.goggle]\non = true\n",
                         "goggle.toml");
}

}  // namespace

// CIGI Sensor Control for view 1 switches the node's second channel into goggle mode (the
// configured class B, the packet's gain without automatic gain) and a later Off back to the
// eye's band; Off also switches off the third channel's goggle, on from the configuration;
// channel 0 is never touched. Through the receiver thread and the frame's pose as the render
// thread takes it (SkyWorker::poseAt).
TEST(CigiSensorControl, SwitchesTheViewsChannelIntoGoggleModeAndBack) {
  const NodeConfig config = goggleConfig();
  ASSERT_EQ(config.channels.size(), 3u);
  ASSERT_FALSE(skyig::sky::isGoggle(config.channels[1]));
  ASSERT_EQ(config.channels[2].band, skyig::sky::SpectralBand::NvisClassA);
  NodeStats workerStats;
  const SkyWorker worker(config, nullptr, workerStats);
  Receiver node;
  UdpSocket host({"127.0.0.1", 0});

  sendSensorControl(host, node.address(), 1, 1, /*on=*/true, /*automaticGain=*/false, 0.375f);
  ASSERT_TRUE(node.handled(1));
  FramePose pose = worker.poseAt(node.latest.get().get(), Clock::now(), config.channels);
  ASSERT_EQ(pose.channels.size(), 3u);
  EXPECT_EQ(pose.channels[1].band, skyig::sky::SpectralBand::NvisClassB);
  EXPECT_TRUE(skyig::sky::isGoggle(pose.channels[1]));
  EXPECT_FALSE(pose.channels[1].goggle.automaticGain);
  EXPECT_EQ(pose.channels[1].goggle.gain, 0.375);
  EXPECT_EQ(pose.channels[1].goggle.phosphor, skyig::sky::Phosphor::P45);
  EXPECT_EQ(pose.channels[1].offset.yawDeg, 30.0);  // the rest of the channel is the configuration's
  EXPECT_EQ(pose.channels[0].band, skyig::sky::SpectralBand::Visible);
  EXPECT_EQ(pose.channels[0].goggle, config.channels[0].goggle);
  EXPECT_EQ(pose.channels[2].band, skyig::sky::SpectralBand::NvisClassA);  // no packet for view 2 yet

  sendSensorControl(host, node.address(), 2, 1, /*on=*/false, /*automaticGain=*/true, 0.0f);
  sendSensorControl(host, node.address(), 3, 2, /*on=*/false, /*automaticGain=*/true, 0.0f);
  ASSERT_TRUE(node.handled(3));
  pose = worker.poseAt(node.latest.get().get(), Clock::now(), config.channels);
  EXPECT_EQ(pose.channels[2].band, skyig::sky::SpectralBand::Visible);
  EXPECT_EQ(pose.channels[1].band, skyig::sky::SpectralBand::Visible);
  EXPECT_TRUE(pose.channels[1].goggle.automaticGain);
  EXPECT_EQ(pose.channels[1].goggle.gain, 0.375);  // gain 0 (sent with automatic gain) keeps the last
  EXPECT_EQ(node.stats.rejectedValues.load(), 0u);
  EXPECT_EQ(node.stats.malformedDatagrams.load(), 0u);
}

// A NaN or out-of-range gain is counted and dropped; the packet's On/Off still applies, and the
// goggle keeps its last good gain.
TEST(CigiSensorControl, NanGainIsCountedAndDroppedWithoutLosingTheSwitch) {
  const NodeConfig config = goggleConfig();
  NodeStats workerStats;
  const SkyWorker worker(config, nullptr, workerStats);
  Receiver node;
  UdpSocket host({"127.0.0.1", 0});

  sendSensorControl(host, node.address(), 1, 1, /*on=*/true, /*automaticGain=*/false, std::nanf(""));
  ASSERT_TRUE(node.handled(1));
  EXPECT_EQ(node.stats.rejectedValues.load(), 1u);
  FramePose pose = worker.poseAt(node.latest.get().get(), Clock::now(), config.channels);
  EXPECT_EQ(pose.channels[1].band, skyig::sky::SpectralBand::NvisClassB);
  EXPECT_FALSE(pose.channels[1].goggle.automaticGain);
  EXPECT_EQ(pose.channels[1].goggle.gain, config.channels[1].goggle.gain);  // the configured gain

  sendSensorControl(host, node.address(), 2, 1, /*on=*/true, /*automaticGain=*/false, 0.5f);
  sendSensorControl(host, node.address(), 3, 1, /*on=*/false, /*automaticGain=*/false, 1.5f);
  ASSERT_TRUE(node.handled(3));
  EXPECT_EQ(node.stats.rejectedValues.load(), 2u);
  pose = worker.poseAt(node.latest.get().get(), Clock::now(), config.channels);
  EXPECT_EQ(pose.channels[1].band, skyig::sky::SpectralBand::Visible);
  EXPECT_EQ(pose.channels[1].goggle.gain, 0.5);  // 1.5 dropped, the last good gain kept
}

namespace {

void sendWeather(UdpSocket& host, const sockaddr_in& to, std::uint32_t frame, const cigi::WeatherControl& w,
                 int cigiVersion = 3) {
  cigi::IgControl ig;
  ig.hostFrameNumber = frame;
  const cigi::Packet packets[] = {ig, w};
  std::vector<std::uint8_t> bytes;
  if (cigiVersion == 4)
    ASSERT_EQ(cigi::encodeMessage4(packets, skyig::protocol::ByteOrder::little, bytes), "");
  else
    ASSERT_EQ(cigi::encodeMessage(packets, skyig::protocol::ByteOrder::big, bytes), "");
  ASSERT_TRUE(host.sendTo(bytes, to));
}

// A node's receiver and sky worker on loopback, and the host that sends them Weather Control. The
// analytic sky: the state carries the host's weather whatever model draws it.
struct WeatherLink {
  NodeConfig config = parseNodeConfig("[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\n", "weather.toml");
  NodeStats workerStats;
  SkyWorker worker{config, nullptr, workerStats};
  Receiver node;
  UdpSocket host{{"127.0.0.1", 0}};
  std::uint32_t frames = 0;
  // `w` as the next host frame (CIGI 3.3 or 4.0), taken by the node; the sky state built then.
  std::optional<skyig::sky::SkyState> send(const cigi::WeatherControl& w, int cigiVersion = 3) {
    sendWeather(host, node.address(), ++frames, w, cigiVersion);
    if (!node.handled(frames)) return std::nullopt;
    return worker.step(node.latest.get().get(), Clock::now(), /*force=*/true);
  }
};

}  // namespace

// CIGI Weather Control, layer 0 (ground fog), global scope, over loopback: its base, thickness
// and visibility become the sky state's fog layer, its transition band the layer's soft top; a
// NaN thickness or a negative band is refused and counted and the layer stays; the host's
// Weather Enable off removes it.
TEST(CigiWeatherControl, GroundFogReachesTheSkyStateAndGoesAgain) {
  WeatherLink link;
  cigi::WeatherControl fog;
  fog.layerId = 0;
  fog.weatherEnable = true;
  fog.scope = cigi::WeatherScope::global;
  fog.baseElevationM = 20.0f;
  fog.thicknessM = 180.0f;
  fog.visibilityRangeM = 400.0f;
  auto state = link.send(fog);
  ASSERT_TRUE(state);
  EXPECT_EQ(state->conditions.fog, (skyig::sky::FogSpec{20.0, 200.0, 0.4}));
  EXPECT_EQ(link.node.latest.get()->state.visibilityM, HostState{}.visibilityM);  // a layer's, not the global's

  cigi::WeatherControl bad = fog;
  bad.thicknessM = std::nanf("");
  state = link.send(bad);
  ASSERT_TRUE(state);
  EXPECT_EQ(link.node.stats.rejectedValues.load(), 1u);
  EXPECT_EQ(state->conditions.fog, (skyig::sky::FogSpec{20.0, 200.0, 0.4}));

  // Its transition band softens the top; a negative band is refused and counted.
  cigi::WeatherControl banded = fog;
  banded.transitionBandM = 60.0f;
  state = link.send(banded);
  ASSERT_TRUE(state);
  EXPECT_EQ(state->conditions.fog.transitionM, 60.0);
  banded.transitionBandM = -5.0f;
  state = link.send(banded);
  ASSERT_TRUE(state);
  EXPECT_EQ(link.node.stats.rejectedValues.load(), 2u);
  EXPECT_EQ(state->conditions.fog.transitionM, 60.0);

  cigi::WeatherControl off = fog;
  off.weatherEnable = false;
  state = link.send(off);
  ASSERT_TRUE(state);
  EXPECT_EQ(state->conditions.fog.visibilityKm, 0.0);
}

// CIGI Weather Control, layers 1-3 (cloud layers), global scope, over loopback in 3.3 and 4.0:
// a stratus deck (layer 1) and a cirrus veil (layer 3, 4.0 with its top scud and top band)
// reach the sky state as the host gave them, and the host's global visibility stays (a layer's
// visibility is inside it); NaN, a coverage over 100, a negative thickness or an unknown type
// ("other", 11) is refused and counted and the last good layer kept; Weather Enable off
// removes it.
TEST(CigiWeatherControl, CloudLayersReachTheSkyStateIn33And40) {
  WeatherLink link;
  auto cloud = [](std::uint8_t layer, std::uint8_t type, float base, float thickness, float coverage) {
    cigi::WeatherControl w;
    w.layerId = layer;
    w.weatherEnable = true;
    w.scope = cigi::WeatherScope::global;
    w.cloudType = type;
    w.baseElevationM = base;
    w.thicknessM = thickness;
    w.coveragePct = coverage;
    return w;
  };
  cigi::WeatherControl deck = cloud(1, 10, 300.0f, 400.0f, 100.0f);  // stratus
  deck.visibilityRangeM = 60.0f;
  deck.transitionBandM = 30.0f;
  deck.severity = 3;
  deck.horizontalWindSpeedMps = 8.0f;
  deck.windDirectionDeg = 270.0f;
  auto state = link.send(deck);
  ASSERT_TRUE(state);
  const skyig::sky::CloudLayer& got = state->conditions.clouds[0];
  EXPECT_TRUE(got.enabled);
  EXPECT_EQ(got.type, skyig::sky::CloudType::Stratus);
  EXPECT_EQ(got.baseM, 300.0);
  EXPECT_EQ(got.thicknessM, 400.0);
  EXPECT_EQ(got.coveragePct, 100.0);
  EXPECT_EQ(got.visibilityM, 60.0);
  EXPECT_EQ(got.transitionM, 30.0);
  EXPECT_EQ(got.topTransitionM, 30.0) << "3.3 has one band for both edges";
  EXPECT_EQ(got.severity, 3);
  EXPECT_EQ(got.windSpeedMps, 8.0);
  EXPECT_EQ(got.windFromDeg, 270.0);
  EXPECT_EQ(link.node.latest.get()->state.visibilityM, HostState{}.visibilityM) << "inside the cloud, not the global";

  cigi::WeatherControl veil = cloud(3, 5, 9000.0f, 800.0f, 40.0f);  // cirrus
  veil.topScudEnable = true;
  veil.topScudFrequencyPct = 20.0f;
  veil.topTransitionBandM = 150.0f;
  state = link.send(veil, 4);
  ASSERT_TRUE(state);
  EXPECT_EQ(state->conditions.clouds[2].type, skyig::sky::CloudType::Cirrus);
  EXPECT_EQ(state->conditions.clouds[2].topTransitionM, 150.0);
  EXPECT_TRUE(state->conditions.clouds[2].topScud);
  EXPECT_EQ(state->conditions.clouds[2].topScudFrequencyPct, 20.0);
  EXPECT_TRUE(state->conditions.clouds[0].enabled) << "layer 1 stays";

  std::uint64_t rejected = link.node.stats.rejectedValues.load();
  for (const auto& spoil : std::vector<std::function<void(cigi::WeatherControl&)>>{
           [](cigi::WeatherControl& w) { w.baseElevationM = std::nanf(""); },
           [](cigi::WeatherControl& w) { w.coveragePct = 150.0f; },
           [](cigi::WeatherControl& w) { w.thicknessM = -10.0f; },
           [](cigi::WeatherControl& w) { w.cloudType = 11; }}) {
    cigi::WeatherControl bad = deck;
    bad.baseElevationM = 1000.0f;  // would move the deck, were the message taken
    spoil(bad);
    state = link.send(bad);
    ASSERT_TRUE(state);
    EXPECT_EQ(link.node.stats.rejectedValues.load(), ++rejected);
    EXPECT_EQ(state->conditions.clouds[0].baseM, 300.0) << "the last good deck kept";
  }

  cigi::WeatherControl off = deck;
  off.weatherEnable = false;
  state = link.send(off);
  ASSERT_TRUE(state);
  EXPECT_FALSE(state->conditions.clouds[0].enabled);
  EXPECT_TRUE(state->conditions.clouds[2].enabled);
}

// CIGI Weather Control, layers 4-9, global scope, over loopback in 3.3 and 4.0: heavy rain with
// no visibility of its own takes its severity's (10 mm/h: 2.5 km); a dust layer over half the
// sky (4.0) joins it in the one precipitation layer the sky draws, tinting it; a coverage of
// 150% is refused and counted; Weather Enable off removes each.
TEST(CigiWeatherControl, PrecipitationLayersReachTheSkyStateIn33And40) {
  WeatherLink link;
  cigi::WeatherControl rain;
  rain.layerId = 4;
  rain.weatherEnable = true;
  rain.severity = 3;
  rain.coveragePct = 100.0f;
  rain.thicknessM = 1500.0f;
  auto state = link.send(rain);
  ASSERT_TRUE(state);
  const skyig::sky::FogSpec heavyRain = state->conditions.precipitation;
  EXPECT_NEAR(heavyRain.visibilityKm, skyig::weather::rainVisibilityKm(10.0), 1e-9);
  EXPECT_EQ(heavyRain.topM, 1500.0);
  EXPECT_EQ(heavyRain.albedo[2], 1.0);

  cigi::WeatherControl dust;
  dust.layerId = 9;
  dust.weatherEnable = true;
  dust.visibilityRangeM = 800.0f;
  dust.coveragePct = 50.0f;
  dust.thicknessM = 1500.0f;
  state = link.send(dust, 4);
  ASSERT_TRUE(state);
  EXPECT_EQ(link.node.latest.get()->state.cigiMajorVersion, 4);
  const skyig::sky::FogSpec both = state->conditions.precipitation;
  EXPECT_NEAR(3.912 / both.visibilityKm, 3.912 / heavyRain.visibilityKm + 3.912 / 1.6, 1e-9);
  EXPECT_LT(both.albedo[2], both.albedo[0]);

  cigi::WeatherControl bad = dust;
  bad.coveragePct = 150.0f;
  state = link.send(bad, 4);
  ASSERT_TRUE(state);
  EXPECT_EQ(link.node.stats.rejectedValues.load(), 1u);
  EXPECT_EQ(state->conditions.precipitation, both);

  cigi::WeatherControl rainOff = rain;
  rainOff.weatherEnable = false;
  state = link.send(rainOff);
  ASSERT_TRUE(state);
  EXPECT_NEAR(state->conditions.precipitation.visibilityKm, 1.6, 1e-9);  // the dust alone
  cigi::WeatherControl dustOff = dust;
  dustOff.weatherEnable = false;
  state = link.send(dustOff, 4);
  ASSERT_TRUE(state);
  EXPECT_EQ(state->conditions.precipitation.visibilityKm, 0.0);
}

// `skyig host` sends Weather Control (layer 0, global) only when its weather is scripted or a fog
// is asked for: otherwise a node keeps the ground fog of its own configuration. The datagram's
// Weather Control carries the fog the command line named.
TEST(HostCommandWeather, GroundFogIsSentOnlyWhenAskedFor) {
  auto firstDatagram = [](const std::string& extra) {
    UdpSocket node({"127.0.0.1", 0});
    const std::string cmd = std::string(SKYIG_EXECUTABLE) + " host --path " + SKYIG_SOURCE_DIR +
                            "/config/circuit.csv --rate 30 --duration 0.01 --to 127.0.0.1:" +
                            std::to_string(node.localEndpoint().port) + " " + extra + " >/dev/null 2>&1";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::array<std::uint8_t, 2048> buffer{};
    sockaddr_in from{};
    const std::size_t n = node.receive(buffer, from, std::chrono::milliseconds(2000));
    return cigi::decodeMessage(std::span<const std::uint8_t>(buffer.data(), n));
  };
  auto fogOf = [](const cigi::DecodedMessage& m) -> std::optional<cigi::WeatherControl> {
    for (const cigi::Packet& p : m.packets)
      if (const auto* w = std::get_if<cigi::WeatherControl>(&p)) return *w;
    return std::nullopt;
  };
  const cigi::DecodedMessage plain = firstDatagram("");
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(fogOf(plain).has_value());
  const cigi::DecodedMessage foggy = firstDatagram("--fog-visibility 300 --fog-top 150");
  ASSERT_TRUE(foggy.ok());
  const auto w = fogOf(foggy);
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->layerId, 0);
  EXPECT_EQ(w->scope, cigi::WeatherScope::global);
  EXPECT_TRUE(w->weatherEnable);
  EXPECT_EQ(w->visibilityRangeM, 300.0f);
  EXPECT_EQ(w->thicknessM, 150.0f);
  EXPECT_EQ(w->baseElevationM, 0.0f);
  // Precipitation, in CIGI 4.0 as in 3.3: every layer 4-9 is sent, the one asked for on.
  for (const char* version : {"3", "4"}) {
    const cigi::DecodedMessage snowy = firstDatagram(std::string("--precipitation snow --precipitation-severity 4 --cigi ") + version);
    ASSERT_TRUE(snowy.ok()) << version;
    EXPECT_EQ(snowy.majorVersion, std::stoi(version));
    int on = 0, off = 0;
    for (const cigi::Packet& p : snowy.packets)
      if (const auto* l = std::get_if<cigi::WeatherControl>(&p); l && l->layerId >= 4) {
        if (!l->weatherEnable) {
          ++off;
          continue;
        }
        ++on;
        EXPECT_EQ(l->layerId, 5);  // snow
        EXPECT_EQ(l->severity, 4);
        EXPECT_EQ(l->visibilityRangeM, 0.0f);  // the severity's
        EXPECT_EQ(l->coveragePct, 100.0f);
        EXPECT_EQ(l->thicknessM, 1500.0f);
      }
    EXPECT_EQ(on, 1) << version;
    EXPECT_EQ(off, 5) << version;
  }
  // A cloud layer (--cloud): Weather Control layer 1 with its type, base, thickness and cover,
  // at the default severity, beside no other weather; a spec that is not one exits 2 naming it.
  const cigi::DecodedMessage cloudy = firstDatagram("--cloud nimbostratus:250:1800:90");
  ASSERT_TRUE(cloudy.ok());
  const auto deck = fogOf(cloudy);
  ASSERT_TRUE(deck.has_value());
  EXPECT_EQ(deck->layerId, 1);
  EXPECT_TRUE(deck->weatherEnable);
  EXPECT_EQ(deck->cloudType, 8);  // nimbostratus
  EXPECT_EQ(deck->baseElevationM, 250.0f);
  EXPECT_EQ(deck->thicknessM, 1800.0f);
  EXPECT_EQ(deck->coveragePct, 90.0f);
  EXPECT_EQ(deck->severity, 2);  // the type's typical water content (physics/weather/cloud_deck.h)
  const std::string bad = std::string(SKYIG_EXECUTABLE) + " host --path " + SKYIG_SOURCE_DIR +
                          "/config/circuit.csv --duration 0.01 --cloud haze:300:400 >/dev/null 2>&1";
  EXPECT_EQ(WEXITSTATUS(std::system(bad.c_str())), 2);
}
