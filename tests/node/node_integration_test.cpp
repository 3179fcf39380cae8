// The IG node on real sockets: skyig host flying a path into a headless node, loss and
// reordering, 100 000 malformed datagrams, Start of Frame back to the host, and CANaerospace
// through a real transport (a socketpair carrying struct can_frame records, since this
// kernel has no SocketCAN).
#include "protocol/canaerospace/state_encoder.h"
#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "node/transport/can_receiver.h"
#include "node/host/host_path.h"
#include "node/node.h"
#include "render/gl/gl_program.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

using namespace skyig::services;
using namespace skyig::services::testing;
namespace cigi = skyig::protocol::cigi;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

// A host message of one IG Control, host frame `frame`.
std::vector<std::uint8_t> igControlOnly(std::uint32_t frame, skyig::protocol::ByteOrder order) {
  cigi::IgControl ig;
  ig.hostFrameNumber = frame;
  const cigi::Packet packets[] = {ig};
  std::vector<std::uint8_t> bytes;
  EXPECT_EQ(cigi::encodeMessage(packets, order, bytes), "");
  return bytes;
}


// A headless node running on its own thread, stopped and joined by stop().
class NodeRun {
 public:
  explicit NodeRun(NodeOptions o) : options_(std::move(o)) {
    thread_ = std::thread([this] {
      try {
        runNode(options_, stats, stop_);
      } catch (const std::exception& e) {
        error = e.what();
      }
      running_ = false;
    });
  }
  ~NodeRun() { stop(); }
  // The first frame: the socket is bound and the renderer up.
  bool waitUntilRendering() {
    return waitUntil([this] { return stats.frames.load() > 0 || !running_; }, kFirstFrameLimit);
  }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  NodeStats stats;
  std::string error;

 private:
  NodeOptions options_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> running_{true};
  std::thread thread_;
};

NodeOptions smallNode(std::uint16_t port, const fs::path& dump) {
  NodeOptions o;
  o.config.sky.model = skyig::sky::SkyModel::Preetham;  // the analytic sky: no tables to load
  o.config.channels.front().width = 32;
  o.config.channels.front().height = 24;
  o.listen = {"127.0.0.1", port};
  o.headless = true;
  o.frameRateHz = 60.0;
  o.dumpStatePath = dump.string();
  return o;
}


long rssKb() {
  std::ifstream in("/proc/self/status");
  std::string key;
  long value = 0;
  while (in >> key) {
    if (key == "VmRSS:") {
      in >> value;
      return value;
    }
    in.ignore(1 << 12, '\n');
  }
  return 0;
}

class NodeIntegration : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshTestDirectory("skyig_node_");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Flies config/circuit.csv for `seconds` at 30 Hz into the node on `port`.
  static void fly(std::uint16_t port, double seconds, const std::string& extra = "") {
    const std::string cmd = std::string(SKYIG_EXECUTABLE) + " host --path " + SKYIG_SOURCE_DIR +
                            "/config/circuit.csv --rate 30 --duration " + std::to_string(seconds) +
                            " --to 127.0.0.1:" + std::to_string(port) + " " + extra + " >/dev/null";
    ASSERT_EQ(std::system(cmd.c_str()), 0);
  }

  // Every dumped frame shows the host values of the path at its host frame, and the values
  // used are those extrapolated by less than a frame and a half of flight.
  static void expectDumpFollowsPath(const std::vector<nlohmann::json>& dump, int& framesWithHost) {
    const HostPath path = HostPath::load(std::string(SKYIG_SOURCE_DIR) + "/config/circuit.csv");
    framesWithHost = 0;
    long lastHostFrame = -1;
    for (const auto& line : dump) {
      if (line["host_frame"].is_null()) continue;
      ++framesWithHost;
      const long k = line["host_frame"].get<long>();
      EXPECT_GE(k, lastHostFrame) << "host frames went backwards";
      lastHostFrame = k;
      const skyig::sky::Ownship expected = path.at(static_cast<double>(k) / 30.0);
      const auto& h = line["host"];
      EXPECT_NEAR(h["lat"].get<double>(), expected.latitudeDeg, 1e-9);
      EXPECT_NEAR(h["lon"].get<double>(), expected.longitudeDeg, 1e-9);
      EXPECT_NEAR(h["alt"].get<double>(), expected.heightM, 1e-6);
      EXPECT_NEAR(h["yaw"].get<double>(), expected.attitude.yawDeg, 1e-4);
      EXPECT_NEAR(h["pitch"].get<double>(), expected.attitude.pitchDeg, 1e-5);
      const auto& u = line["used"];
      EXPECT_NEAR(u["lat"].get<double>(), h["lat"].get<double>(), 2e-5);  // < ~2 m: at most 0.25 s of flight
      EXPECT_NEAR(u["alt"].get<double>(), h["alt"].get<double>(), 3.0);
    }
  }

  // A node on `port` flown the path's first 2 s at 30 Hz (`extra`: the host's flags), then
  // stopped: it ran without error, and its dump follows the path in more than 60 frames.
  void flyAndCheckTheDump(NodeRun& node, std::uint16_t port, const std::string& extra = "") {
    ASSERT_TRUE(node.waitUntilRendering());
    fly(port, 2.0, extra);
    ASSERT_TRUE(waitForFrames(node.stats.frames, 3));
    node.stop();
    ASSERT_TRUE(node.error.empty()) << node.error;
    int withHost = 0;
    expectDumpFollowsPath(readStateDump(dir_ / "dump.jsonl"), withHost);
    EXPECT_GT(withHost, 60);
  }

  fs::path dir_;
};

}  // namespace

TEST_F(NodeIntegration, HostToHeadlessNodeDumpsTheFlownPath) {
  const std::uint16_t port = freeLoopbackPort();
  NodeRun node(smallNode(port, dir_ / "dump.jsonl"));
  flyAndCheckTheDump(node, port);
  EXPECT_EQ(node.stats.malformedDatagrams.load(), 0u);
  EXPECT_EQ(node.stats.datagrams.load(), 61u);  // 2 s at 30 Hz, frames 0..60
  // The host's date and time reached the sky: the dump's clock runs from 19:00:00.
  const auto last = readStateDump(dir_ / "dump.jsonl").back();
  EXPECT_EQ(last["used"]["utc"].get<std::string>().substr(0, 17), "2026-06-21T19:00:");
}

TEST_F(NodeIntegration, LossAndReorderingDoNotBreakIt) {
  const std::uint16_t port = freeLoopbackPort();
  NodeRun node(smallNode(port, dir_ / "dump.jsonl"));
  flyAndCheckTheDump(node, port, "--drop-every 10 --swap-pairs");
  EXPECT_GT(node.stats.staleMessages.load(), 10u);  // the late half of each swapped pair
}

TEST_F(NodeIntegration, StartOfFrameGoesBackToTheHost) {
  UdpSocket host({"127.0.0.1", 0});
  const std::uint16_t port = freeLoopbackPort();
  NodeOptions o = smallNode(port, dir_ / "dump.jsonl");
  o.replyPort = host.localEndpoint().port;
  NodeRun node(o);
  ASSERT_TRUE(node.waitUntilRendering());
  ASSERT_TRUE(host.sendTo(igControlOnly(4242, skyig::protocol::ByteOrder::little), toSockaddr({"127.0.0.1", port})));
  std::array<std::uint8_t, 2048> buffer{};
  sockaddr_in from{};
  std::uint32_t lastIgFrame = 0;
  int received = 0, beforeShown = 0;
  bool shown = false;
  // The host is answered from the first frame after its datagram arrives (judged alive by the
  // receiver); a frame drawn before the worker built a sky from it names no host frame (0), and
  // once one names 4242 every later one does.
  for (int i = 0; i < 20; ++i) {
    const std::size_t n = host.receive(buffer, from, 500ms);
    ASSERT_GT(n, 0u);
    const cigi::DecodedMessage m = cigi::decodeMessage(std::span(buffer.data(), n));
    ASSERT_TRUE(m.ok()) << m.error->describe();
    const auto* sof = std::get_if<cigi::StartOfFrame>(&m.packets.front());
    ASSERT_NE(sof, nullptr);
    if (!shown && sof->lastHostFrameNumber == 0u) {
      ++beforeShown;
    } else {
      shown = true;
      EXPECT_EQ(sof->lastHostFrameNumber, 4242u);
    }
    if (received++ > 0) {
      EXPECT_GT(sof->igFrameNumber, lastIgFrame);
    }
    lastIgFrame = sof->igFrameNumber;
  }
  EXPECT_TRUE(shown) << "no Start of Frame named the host's frame";
  std::printf("%d Start of Frames before the sky showed the host's frame\n", beforeShown);
  node.stop();
}

// A node whose frames take longer to draw than the session gap still answers every frame it
// draws while its host speaks: the host is judged alive at the frame's start. Here a 20 ms gap
// and 1280 x 960 frames (tens of milliseconds on llvmpipe) with the host sending every 2 ms:
// before, the node judged at the frame's end and sent no Start of Frame at all.
TEST_F(NodeIntegration, AFrameSlowerThanTheSessionGapStillAnswersTheHost) {
  UdpSocket host({"127.0.0.1", 0});
  const std::uint16_t port = freeLoopbackPort();
  NodeOptions o = smallNode(port, dir_ / "dump.jsonl");
  o.replyPort = host.localEndpoint().port;
  o.config.channels.front().width = 1280;
  o.config.channels.front().height = 960;
  o.config.host.session.sessionGapS = 0.02;
  NodeRun node(o);
  ASSERT_TRUE(node.waitUntilRendering());
  std::atomic<bool> sending{true};
  std::thread sender([&] {
    for (std::uint32_t n = 1; sending; ++n) {
      host.sendTo(igControlOnly(n, skyig::protocol::ByteOrder::big), toSockaddr({"127.0.0.1", port}));
      std::this_thread::sleep_for(2ms);
    }
  });
  ASSERT_TRUE(waitUntil([&] { return node.stats.datagrams.load() > 10; }));
  const std::uint64_t framesBefore = node.stats.frames.load(), sentBefore = node.stats.startOfFrameSent.load();
  ASSERT_TRUE(waitForFrames(node.stats.frames, framesBefore + 20));
  const std::uint64_t frames = node.stats.frames.load() - framesBefore;
  const std::uint64_t sent = node.stats.startOfFrameSent.load() - sentBefore;
  sending = false;
  sender.join();
  const double frameMs = node.stats.frameTime.summary().value("p50_us", 0.0) / 1000.0;
  node.stop();
  std::printf("frames of %.0f ms (p50) against a 20 ms session gap: %llu Start of Frames for %llu frames\n", frameMs,
              static_cast<unsigned long long>(sent), static_cast<unsigned long long>(frames));
  ASSERT_GT(frameMs, 20.0) << "the frames must be slower than the gap for this to show anything";
  EXPECT_GE(2 * sent, frames);
}

// Start of Frame answers only the followed host: a sender outside host.allowed (here a spoofed
// 127.0.0.2 listening on the reply port) gets nothing however long the node runs, and is
// counted; the allowed host that then speaks is answered on its own address.
TEST_F(NodeIntegration, StartOfFrameNeverGoesToASenderOutsideAllowed) {
  UdpSocket spoofed({"127.0.0.2", 0});
  const std::uint16_t replyPort = spoofed.localEndpoint().port;
  UdpSocket host({"127.0.0.1", replyPort});
  const std::uint16_t port = freeLoopbackPort();
  NodeOptions o = smallNode(port, dir_ / "dump.jsonl");
  o.replyPort = replyPort;
  o.config.host.session.allowed = {parseAddressRange("127.0.0.1/32")};
  NodeRun node(o);
  ASSERT_TRUE(node.waitUntilRendering());
  const std::vector<std::uint8_t> bytes = igControlOnly(7, skyig::protocol::ByteOrder::big);
  ASSERT_TRUE(spoofed.sendTo(bytes, toSockaddr({"127.0.0.1", port})));
  ASSERT_TRUE(waitUntil([&] { return node.stats.notAllowedDatagrams.load() == 1; }));
  ASSERT_TRUE(waitForFrames(node.stats.frames, 10));
  std::array<std::uint8_t, 2048> buffer{};
  sockaddr_in from{};
  EXPECT_EQ(spoofed.receive(buffer, from, 300ms), 0u);
  EXPECT_EQ(node.stats.startOfFrameSent.load(), 0u);
  ASSERT_TRUE(host.sendTo(bytes, toSockaddr({"127.0.0.1", port})));
  // Start of Frame names the host frame the IG frame showed: those drawn before the worker built
  // a sky from the host's datagram name none (0); the host's own frame follows within a few.
  std::uint32_t named = 0;
  for (int i = 0; i < 20 && named == 0; ++i) {
    const std::size_t n = host.receive(buffer, from, 2000ms);
    ASSERT_GT(n, 0u);
    const cigi::DecodedMessage m = cigi::decodeMessage(std::span(buffer.data(), n));
    ASSERT_TRUE(m.ok());
    ASSERT_NE(std::get_if<cigi::StartOfFrame>(&m.packets.front()), nullptr);
    named = std::get<cigi::StartOfFrame>(m.packets.front()).lastHostFrameNumber;
  }
  EXPECT_EQ(named, 7u);
  EXPECT_EQ(spoofed.receive(buffer, from, 100ms), 0u);
  node.stop();
}

namespace {
// Runs `command`, returns its standard output.
std::string outputOf(const std::string& command) {
  std::string out;
  FILE* p = popen(command.c_str(), "r");
  if (!p) return out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, p)) out += buf;
  EXPECT_EQ(pclose(p), 0) << command;
  return out;
}

// "00 18 FF FF" -> bytes.
std::vector<std::uint8_t> parseHex(const std::string& text) {
  std::vector<std::uint8_t> bytes;
  std::istringstream in(text);
  std::string b;
  while (in >> b) bytes.push_back(static_cast<std::uint8_t>(std::stoul(b, nullptr, 16)));
  return bytes;
}

std::uint32_t bigEndianU32(const std::vector<std::uint8_t>& b, std::size_t off) {
  return (std::uint32_t{b[off]} << 24) | (std::uint32_t{b[off + 1]} << 16) | (std::uint32_t{b[off + 2]} << 8) | b[off + 3];
}
}  // namespace

// A CIGI 4.0 host is answered in CIGI 4.0: `skyig host --cigi 4` flies into the node, reads the
// node's Start of Frame on its own socket and prints the last one; its bytes follow the 4.0
// layout (u16 size 24, u16 id 0xFFFF, major 4, no byte-swap magic; CIGI 4.0 ICD as CCL 4.0's
// CigiSOFV4 packs it). The host's 4.0 seconds reach the sky's clock: started at 19:00:30, the
// node shows 19:00:30 and more, where a 3.3 host (minutes only) would give 19:00:00.
TEST_F(NodeIntegration, Cigi4HostGetsCigi4StartOfFrameBack) {
  const std::uint16_t port = freeLoopbackPort();
  const std::uint16_t hostPort = freeLoopbackPort();
  NodeOptions o = smallNode(port, dir_ / "dump.jsonl");
  o.replyPort = hostPort;
  o.statsPath = (dir_ / "stats.json").string();
  NodeRun node(o);
  ASSERT_TRUE(node.waitUntilRendering());
  const std::string out = outputOf(std::string(SKYIG_EXECUTABLE) + " host --cigi 4 --path " + SKYIG_SOURCE_DIR +
                                   "/config/circuit.csv --rate 30 --duration 1 --start-utc 2026-06-21T19:00:30Z --to 127.0.0.1:" +
                                   std::to_string(port) + " --bind 127.0.0.1:" + std::to_string(hostPort));
  ASSERT_TRUE(waitForFrames(node.stats.frames, 3));
  node.stop();
  ASSERT_TRUE(node.error.empty()) << node.error;
  EXPECT_EQ(node.stats.malformedDatagrams.load(), 0u);
  EXPECT_EQ(node.stats.datagrams.load(), 31u);  // 1 s at 30 Hz, frames 0..30
  const std::string tag = "host: last Start of Frame bytes: ";
  const auto at = out.find(tag);
  ASSERT_NE(at, std::string::npos) << out;
  const std::vector<std::uint8_t> b = parseHex(out.substr(at + tag.size(), out.find('\n', at) - at - tag.size()));
  ASSERT_EQ(b.size(), 24u) << out;
  // Size 24, id 0xFFFF, major 4, database 0, reserved, IG mode operate (1) | timestamp valid
  // (bit 2) | minor 0 (bits 4-7), all big-endian as the node writes.
  EXPECT_EQ(std::vector<std::uint8_t>(b.begin(), b.begin() + 8), (std::vector<std::uint8_t>{0x00, 0x18, 0xFF, 0xFF, 0x04, 0x00, 0x00, 0x05}));
  const std::uint32_t igFrame = bigEndianU32(b, 8), timestamp = bigEndianU32(b, 12), lastHostFrame = bigEndianU32(b, 16);
  EXPECT_GT(igFrame, 0u);
  EXPECT_GT(timestamp, 0u);  // 10 us ticks since the node started
  EXPECT_LE(lastHostFrame, 30u);
  EXPECT_GT(lastHostFrame, 0u);  // an answer to a host frame that came after the first
  EXPECT_EQ(bigEndianU32(b, 20), 0u);  // no overframing, paging or excess-data condition
  // The codec reads the same bytes as a 4.0 Start of Frame with those fields.
  const cigi::DecodedMessage m = cigi::decodeMessage(b);
  ASSERT_TRUE(m.ok()) << m.error->describe();
  EXPECT_EQ(m.majorVersion, 4);
  const auto& sof = std::get<cigi::StartOfFrame>(m.packets.at(0));
  EXPECT_EQ(sof.igFrameNumber, igFrame);
  EXPECT_EQ(sof.lastHostFrameNumber, lastHostFrame);
  EXPECT_EQ(sof.timestamp, timestamp);
  EXPECT_NE(out.find("Start of Frame: CIGI 4.0, IG frame " + std::to_string(igFrame)), std::string::npos) << out;
  // The host's seconds: every dumped frame with a host time is 19:00:30 or later (and the run lasts seconds).
  int withTime = 0;
  for (const auto& line : readStateDump(dir_ / "dump.jsonl")) {
    if (line["host_frame"].is_null()) continue;
    const std::string utc = line["used"]["utc"].get<std::string>();
    EXPECT_TRUE(utc >= "2026-06-21T19:00:30" && utc < "2026-06-21T19:00:40") << utc;
    ++withTime;
  }
  EXPECT_GT(withTime, 10);
  // The statistics name their counters in snake_case, units in the name.
  std::ifstream statsFile(dir_ / "stats.json");
  const nlohmann::json stats = nlohmann::json::parse(statsFile);
  EXPECT_EQ(stats["datagrams"].get<std::uint64_t>(), 31u);
  EXPECT_EQ(stats["packets"]["ig_control"].get<std::uint64_t>(), 31u);
  EXPECT_EQ(stats["packets"]["celestial_sphere_control"].get<std::uint64_t>(), 31u);
  EXPECT_EQ(stats["errors"]["wrong_packet_size"].get<std::uint64_t>(), 0u);
  EXPECT_GT(stats["start_of_frame_sent"].get<std::uint64_t>(), 0u);
  EXPECT_TRUE(stats["latency"]["frame_render"].contains("p50_us"));
  EXPECT_TRUE(stats["can"].contains("pending_double_half"));
}

// 100 000 malformed datagrams, in bursts at full speed: the node keeps rendering, counts them,
// its memory stays flat and the last good state is kept.
TEST_F(NodeIntegration, SurvivesOneHundredThousandMalformedDatagrams) {
  const std::uint16_t port = freeLoopbackPort();
  NodeRun node(smallNode(port, dir_ / "dump.jsonl"));
  ASSERT_TRUE(node.waitUntilRendering());
  UdpSocket attacker({"127.0.0.1", 0});
  const sockaddr_in to = toSockaddr({"127.0.0.1", port});
  // One good state first.
  cigi::IgControl ig;
  ig.hostFrameNumber = 1;
  cigi::EntityControl e;
  e.latitudeDeg = 51.4775;
  e.longitudeDeg = -0.4614;
  e.altitudeM = 100.0;
  e.yawDeg = 270.0f;
  const cigi::Packet good[] = {ig, e};
  std::vector<std::uint8_t> bytes;
  ASSERT_EQ(cigi::encodeMessage(good, skyig::protocol::ByteOrder::big, bytes), "");
  ASSERT_TRUE(attacker.sendTo(bytes, to));
  // The good state's sky is drawn and everything its first frames load (the moon's map, the
  // star catalogue) is resident before the memory is measured.
  ASSERT_TRUE(waitUntil([&] { return node.stats.datagrams.load() >= 1; }));
  ASSERT_TRUE(waitForFrames(node.stats.frames, 30));
  const long rssBefore = rssKb();
  const std::uint64_t framesBefore = node.stats.frames.load();
  const std::uint64_t datagramsBefore = node.stats.datagrams.load();

  std::mt19937 rng(12345);
  std::vector<std::uint8_t> junk;
  constexpr int kCount = 100000;
  for (int i = 0; i < kCount; ++i) {
    // Mostly plausible-looking CIGI (a real header with a wrong size or version), some noise.
    junk = bytes;
    switch (i % 4) {
      case 0: junk.resize(rng() % bytes.size()); break;            // truncated
      case 1: junk[1] = static_cast<std::uint8_t>(rng()); break;    // wrong packet size
      case 2: junk[4] = static_cast<std::uint8_t>(rng() % 3); break;  // wrong version
      default:
        for (auto& b : junk) b = static_cast<std::uint8_t>(rng());
    }
    if (junk == bytes || junk.empty()) junk.assign({0x01});
    attacker.sendTo(junk, to);
    // Let loopback's queue drain after each burst: what overflows the socket's buffer is dropped,
    // and a slower receiver must not fail the test (under ASan, 22% were lost with a fixed 1 ms
    // pause every 2000). Drained: the node has them all, or its count stopped moving.
    if (i % 250 == 249) {
      std::uint64_t seen = ~std::uint64_t{0};
      waitUntil([&] {
        const std::uint64_t now = node.stats.datagrams.load() - datagramsBefore;
        const bool drained = now >= static_cast<std::uint64_t>(i) + 1 || now == seen;
        seen = now;
        return drained;
      }, 2s);
    }
  }
  // Drained: the counts stop moving (loopback drops what overflows the socket's buffer).
  std::uint64_t seen = 0;
  waitUntil([&] {
    const std::uint64_t now = node.stats.datagrams.load();
    const bool still = now == seen;
    seen = now;
    std::this_thread::sleep_for(50ms);
    return still;
  });
  ASSERT_TRUE(waitForFrames(node.stats.frames, 11));
  const long rssAfter = rssKb();
  node.stop();
  ASSERT_TRUE(node.error.empty()) << node.error;
  EXPECT_GT(node.stats.malformedDatagrams.load(), kCount * 95 / 100);
  EXPECT_GT(node.stats.frames.load(), framesBefore + 10);  // it kept rendering
#ifndef __SANITIZE_ADDRESS__
  EXPECT_LT(rssAfter - rssBefore, 8 * 1024) << "RSS grew from " << rssBefore << " kB to " << rssAfter << " kB";
#else
  // AddressSanitizer keeps freed memory in quarantine (256 MB) to catch use after free, so RSS
  // grows by design (30 MB here); its leak check at exit stands in for this one.
  (void)rssBefore;
  (void)rssAfter;
#endif
  const auto last = readStateDump(dir_ / "dump.jsonl").back();
  EXPECT_NEAR(last["host"]["lat"].get<double>(), 51.4775, 1e-9);  // the last good state
  EXPECT_NEAR(last["used"]["yaw"].get<double>(), 270.0, 1e-9);
}

TEST_F(NodeIntegration, CanAerospaceThroughARealTransport) {
  int fds[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_SEQPACKET, 0, fds), 0);
  const std::uint16_t port = freeLoopbackPort();
  NodeOptions o = smallNode(port, dir_ / "dump.jsonl");
  o.canFd = fds[0];
  NodeRun node(o);
  ASSERT_TRUE(node.waitUntilRendering());
  skyig::protocol::canaerospace::CanAerospaceState s;
  s.latitudeDeg = 47.2603;
  s.longitudeDeg = 11.3439;
  s.altitudeM = 700.0;
  s.headingDeg = 120.0;
  s.pitchDeg = 4.0;
  s.rollDeg = -10.0;
  s.hour = 21;
  s.minute = 14;
  s.second = 30;
  s.year = 2026;
  s.month = 3;
  s.day = 7;
  skyig::protocol::canaerospace::StateEncoder encoder;
  const auto frames = encoder.encode(s);
  const auto sent = std::chrono::steady_clock::now();
  for (const auto& frame : frames) ASSERT_EQ(::write(fds[1], &frame, sizeof frame), static_cast<ssize_t>(sizeof frame));
  ASSERT_TRUE(waitUntil([&] { return node.stats.canFrames.load() >= frames.size(); }));
  // Until a frame shows the CAN host's state: the worker builds it after the frames arrive, a
  // few frames later on a loaded machine (a sanitizer build beside another test).
  ASSERT_TRUE(waitUntil([&] {
    const auto lines = readStateDump(dir_ / "dump.jsonl");
    return !lines.empty() && std::abs(lines.back()["used"]["alt"].get<double>() - 700.0) < 1e-3;
  }));
  node.stop();
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  ::close(fds[0]);
  ::close(fds[1]);
  ASSERT_TRUE(node.error.empty()) << node.error;
  const auto last = readStateDump(dir_ / "dump.jsonl").back();
  EXPECT_NEAR(last["used"]["lat"].get<double>(), 47.2603, 1e-9);  // DOUBLEH+DOUBLEL pairs: full precision
  EXPECT_NEAR(last["used"]["lon"].get<double>(), 11.3439, 1e-9);
  EXPECT_NEAR(last["used"]["alt"].get<double>(), 700.0, 1e-3);
  EXPECT_NEAR(last["used"]["yaw"].get<double>(), 120.0, 1e-4);
  EXPECT_NEAR(last["used"]["roll"].get<double>(), -10.0, 1e-4);
  // The host's time, run on by the sim clock from the message to the last frame dumped (a loaded
  // machine under ASan takes seconds for the three frames).
  const std::string utc = last["used"]["utc"].get<std::string>();
  EXPECT_EQ(utc.substr(0, 17), "2026-03-07T21:14:") << utc;
  const double second = std::stod(utc.substr(17));
  EXPECT_GE(second, 30.0) << utc;
  EXPECT_LE(second, 30.0 + elapsed + 0.1) << utc << " after " << elapsed << " s";
  EXPECT_GE(node.stats.canFrames.load(), 8u);
}

// A host that switches a channel's goggle on (Sensor Control) finds its programs compiled: the
// node warms every channel up with its goggle switched too, so the first goggle frame links no
// program (before, it compiled the goggle's passes mid-frame: 0.6-0.8 s on llvmpipe). Off again,
// the same.
TEST_F(NodeIntegration, SwitchingTheGoggleCompilesNothingMidFrame) {
  const std::uint16_t port = freeLoopbackPort();
  NodeRun node(smallNode(port, dir_ / "dump.jsonl"));
  ASSERT_TRUE(node.waitUntilRendering());
  const std::size_t linked = skyig::render::programsLinked();
  UdpSocket host({"127.0.0.1", 0});
  const sockaddr_in to = toSockaddr({"127.0.0.1", port});
  auto send = [&](std::uint32_t frame, bool goggleOn) {
    cigi::IgControl ig;
    ig.hostFrameNumber = frame;
    cigi::SensorControl sensor;
    sensor.viewId = 0;
    sensor.sensorOn = goggleOn;
    sensor.automaticGain = true;
    const cigi::Packet packets[] = {ig, sensor};
    std::vector<std::uint8_t> bytes;
    ASSERT_EQ(cigi::encodeMessage(packets, skyig::protocol::ByteOrder::big, bytes), "");
    ASSERT_TRUE(host.sendTo(bytes, to));
  };
  auto lastGoggle = [&] {
    const auto dump = readStateDump(dir_ / "dump.jsonl");
    return dump.empty() ? false : dump.back()["used"]["views"][0]["goggle"]["on"].get<bool>();
  };
  send(1, true);
  ASSERT_TRUE(waitUntil([&] { return lastGoggle(); }, kFirstFrameLimit));
  ASSERT_TRUE(waitForFrames(node.stats.frames, node.stats.frames.load() + 5));
  EXPECT_EQ(skyig::render::programsLinked(), linked) << "the goggle's first frames linked programs";
  send(2, false);
  ASSERT_TRUE(waitUntil([&] { return !lastGoggle(); }, kFirstFrameLimit));
  ASSERT_TRUE(waitForFrames(node.stats.frames, node.stats.frames.load() + 5));
  EXPECT_EQ(skyig::render::programsLinked(), linked);
  node.stop();
  EXPECT_TRUE(node.error.empty()) << node.error;
}

TEST(SocketCan, FailsClearlyWhereTheKernelHasNoCan) {
  const int probe = ::socket(PF_CAN, SOCK_RAW, 1);
  const bool kernelHasCan = probe >= 0 || errno != EAFNOSUPPORT;
  if (probe >= 0) ::close(probe);
  try {
    ::close(openSocketCan("skyig-no-such-can0"));
    FAIL() << "opened a CAN interface that does not exist";
  } catch (const NetworkError& e) {
    const std::string what = e.what();
    if (kernelHasCan) {
      EXPECT_NE(what.find("skyig-no-such-can0"), std::string::npos) << what;
    } else {
      EXPECT_NE(what.find("no CAN support"), std::string::npos) << what;
    }
  }
}
