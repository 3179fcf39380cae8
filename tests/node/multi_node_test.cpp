// Many nodes in step: two `skyig serve` processes, nodes ig1 and ig2 of one dome configuration,
// in synchronous mode on a multicast group, fed by one `skyig host`. Each renders the host's
// frame N as its frame for N (the sky built from that host frame, the attitude at its instant),
// says so in its Start of Frame, and what it derives from the host's state (the eye's
// adaptation, the sun, the attitude) is identical on both; a view both render matches pixel for
// pixel, and the directions two overlapping channels of different nodes share match within the
// dither. Multicast stays on loopback: joined on 127.0.0.1, sent through it with TTL 0.
//
// MultiNodeDome is the harness: a configuration, nodes started by name, the host flown, then
// per node the host frames it showed (state dump), its Start of Frames and its saved frames.
#include "calibration/dome.h"
#include "calibration/load.h"
#include "protocol/cigi/decoder.h"
#include "render/image_io.h"
#include "node/config/node_config.h"
#include "node/config/sky_data.h"
#include "node/frame/sky_worker.h"
#include "sky/camera.h"
#include "physics/common/png_reader.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <fstream>
#include <functional>
#include <optional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

using namespace skyig::services;
using namespace skyig::services::testing;
namespace cigi = skyig::protocol::cigi;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

// The complete lines of a state dump the node may be writing (a line being written is left
// for the next look).
std::vector<nlohmann::json> completeDumpLines(const fs::path& p) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) {
    nlohmann::json j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
    if (j.is_discarded()) break;
    lines.push_back(std::move(j));
  }
  return lines;
}

struct StartOfFrameSeen {
  std::uint32_t igFrame = 0;
  std::uint32_t lastHostFrame = 0;
};

// One node of the dome: its `serve` process, what it writes, and the Start of Frames it sends
// (each node answers on a socket of its own: on one machine the nodes share the group's port,
// so the host could not tell them apart).
struct DomeNode {
  std::string name;
  fs::path dump, frames, log, stats;
  fs::path recording;  // its host stream, when the dome records (MultiNodeDome::record_)
  std::unique_ptr<UdpSocket> startOfFrame;
  std::vector<StartOfFrameSeen> sofs;
  std::unique_ptr<SkyigProcess> process;

  // The first dump line of each host frame the node showed.
  std::map<std::uint32_t, nlohmann::json> hostFrames() const {
    std::map<std::uint32_t, nlohmann::json> shown;
    for (const auto& line : completeDumpLines(dump))
      if (line["host_frame"].is_number()) shown.emplace(line["host_frame"].get<std::uint32_t>(), line);
    return shown;
  }
  // The file the node saved for IG frame `igFrame` and `channel` ("" when none; a node with one
  // channel names no channel in its files: pass "").
  fs::path savedFrame(std::uint64_t igFrame, const std::string& channel, const std::string& extension) const {
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "frame_%06llu_", static_cast<unsigned long long>(igFrame));
    const std::string suffix = (channel.empty() ? "" : "_" + channel) + extension;
    for (const auto& e : fs::directory_iterator(frames)) {
      const std::string n = e.path().filename().string();
      if (n.rfind(prefix, 0) == 0 && n.size() > suffix.size() && n.compare(n.size() - suffix.size(), suffix.size(), suffix) == 0)
        return e.path();
    }
    return {};
  }
};

class MultiNodeDome : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshTestDirectory("skyig_multi_node_");
    port_ = freeLoopbackPort();
    hostPort_ = freeLoopbackPort();
    // A group of this process's own, so parallel test runs on one machine never hear each other.
    group_ = "239.255." + std::to_string(100 + ::getpid() % 100) + "." + std::to_string(1 + ::getpid() / 100 % 250);
  }
  void TearDown() override {
    stopNodes();
    if (!HasFailure()) fs::remove_all(dir_);
  }

  // The dome's configuration: the host link (synchronous, the group joined on loopback) and
  // `channels` ([[channel]] tables, `node` keys selecting who renders what).
  void writeConfig(const std::string& sky, const std::string& channels) {
    config_ = dir_ / "dome.toml";
    std::ofstream(config_) << sky << "\n[host]\nlisten = \"0.0.0.0:" << port_ << "\"\nmulticast_group = \"" << group_
                           << "\"\nmulticast_interface = \"127.0.0.1\"\nsynchronous = true\nsync_timeout = 0.5\n"
                           << channels;
  }

  // Starts `serve` for each node name and waits until each has drawn its first frame. Each node
  // answers on a socket of the harness's (DomeNode::sofs), or with `answerTheHost` the host
  // (`skyig host --lockstep` waits for the answers).
  void startNodes(const std::vector<std::string>& names, bool answerTheHost = false) {
    for (const std::string& name : names) {
      auto n = std::make_unique<DomeNode>();
      n->name = name;
      n->dump = dir_ / (name + ".jsonl");
      n->frames = dir_ / (name + "-frames");
      n->log = dir_ / (name + ".log");
      n->stats = dir_ / (name + "-stats.json");
      if (record_) n->recording = dir_ / (name + ".pcap");
      n->startOfFrame = std::make_unique<UdpSocket>(Endpoint{"127.0.0.1", 0});
      n->process = std::make_unique<SkyigProcess>(
          "serve --config " + config_.string() + " --node " + name + " --headless --dump-state " + n->dump.string() +
              " --stats-json " + n->stats.string() +
              (n->recording.empty() ? std::string() : " --record " + n->recording.string()) +
              " --save-frames " + n->frames.string() + " --save-every 1 --reply-to " +
              (answerTheHost ? "127.0.0.1:" + std::to_string(hostPort_) : n->startOfFrame->localEndpoint().toString()),
          n->log);
      nodes_.push_back(std::move(n));
    }
    for (auto& n : nodes_)
      ASSERT_TRUE(waitUntil([&] { return !n->process->running() || completeDumpLines(n->dump).size() > 0; }, kFirstFrameLimit))
          << n->name;
    for (auto& n : nodes_) ASSERT_TRUE(n->process->running()) << n->name << ":\n" << n->process->output();
    listening_ = true;
    listener_ = std::thread([this] { listen(); });
  }

  // Flies `skyig host` to the group (through 127.0.0.1, TTL 0) and returns its exit code.
  int flyHost(const std::string& args) {
    SkyigProcess host("host " + args + " --to " + group_ + ":" + std::to_string(port_) +
                          " --bind 127.0.0.1:" + std::to_string(hostPort_) +
                          " --multicast-interface 127.0.0.1 --multicast-ttl 0",
                      dir_ / "host.log");
    const int code = host.wait();
    hostOutput_ = host.output();
    return code;
  }

  // Waits until every node showed host frame `last`, then stops them (exit code 0 each).
  void finish(std::uint32_t last) {
    for (auto& n : nodes_)
      EXPECT_TRUE(waitUntil([&] { return n->hostFrames().count(last) > 0; }, 30000ms)) << n->name << " never showed " << last;
    std::this_thread::sleep_for(100ms);  // the last Start of Frames arrive
    for (auto& n : nodes_) EXPECT_EQ(n->process->stop(), 0) << n->name << ":\n" << n->process->output();
    stopNodes();
  }

  void stopNodes() {
    listening_ = false;
    if (listener_.joinable()) listener_.join();
    for (auto& n : nodes_) n->process->stop();
  }

  DomeNode& node(const std::string& name) {
    for (auto& n : nodes_)
      if (n->name == name) return *n;
    throw std::invalid_argument("no node " + name);
  }

  fs::path dir_;
  std::string hostOutput_;
  bool record_ = false;  // each node started records its host stream (DomeNode::recording)

 private:
  void listen() {
    std::array<std::uint8_t, 512> buffer{};
    while (listening_) {
      for (auto& n : nodes_) {
        sockaddr_in from{};
        const std::size_t size = n->startOfFrame->receive(buffer, from, 2ms);
        if (size == 0) continue;
        const cigi::DecodedMessage m = cigi::decodeMessage(std::span(buffer.data(), size));
        if (!m.ok() || m.packets.empty()) continue;
        if (const auto* s = std::get_if<cigi::StartOfFrame>(&m.packets.front())) {
          const std::lock_guard lock(mutex_);
          n->sofs.push_back({s->igFrameNumber, s->lastHostFrameNumber});
        }
      }
    }
  }

  std::uint16_t port_ = 0;      // the group's
  std::uint16_t hostPort_ = 0;  // the host's (its Start of Frames arrive there)
  std::string group_;
  fs::path config_;
  std::vector<std::unique_ptr<DomeNode>> nodes_;
  std::atomic<bool> listening_{false};
  std::thread listener_;
  std::mutex mutex_;
};

// The ENU ray of a channel pixel, from a state dump line (ownship attitude and the channel's
// view as drawn).
glm::dmat3 channelNdcToWorld(const nlohmann::json& used, const std::string& channel) {
  for (const auto& v : used["views"])
    if (v["channel"] == channel) {
      const skyig::sky::Attitude ownship{used["yaw"].get<double>(), used["pitch"].get<double>(), used["roll"].get<double>()};
      const skyig::sky::Attitude offset{v["yaw"].get<double>(), v["pitch"].get<double>(), v["roll"].get<double>()};
      const skyig::sky::Frustum f{v["left"].get<double>(), v["right"].get<double>(), v["down"].get<double>(),
                                  v["up"].get<double>()};
      return skyig::sky::ndcToWorld(skyig::sky::eyeToEnu(ownship, offset), f);
    }
  throw std::invalid_argument("no channel " + channel + " in the dump");
}

// Bilinear sample of channel c (0..2) of an 8-bit RGB image at pixel coordinates (x, y), pixel
// centres at integer + 0.5.
double sampleRgb8(const skyig::sky::Rgb8Image& image, double x, double y, int c) {
  const double u = x - 0.5, v = y - 0.5;
  const int x0 = static_cast<int>(std::floor(u)), y0 = static_cast<int>(std::floor(v));
  const double fx = u - x0, fy = v - y0;
  auto at = [&](int column, int row) {
    return static_cast<double>(image.rgb[(static_cast<std::size_t>(row) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(column)) * 3 + static_cast<std::size_t>(c)]);
  };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) + fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
}

// The largest difference (LSB, any colour) among the four pixels around (x, y).
constexpr int kSmoothLsb = 6;
int localRange(const skyig::sky::Rgb8Image& image, double x, double y) {
  const int x0 = static_cast<int>(std::floor(x - 0.5)), y0 = static_cast<int>(std::floor(y - 0.5));
  int range = 0;
  for (int c = 0; c < 3; ++c) {
    int lo = 255, hi = 0;
    for (int dy = 0; dy < 2; ++dy)
      for (int dx = 0; dx < 2; ++dx) {
        const int v = image.rgb[(static_cast<std::size_t>(y0 + dy) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x0 + dx)) * 3 + static_cast<std::size_t>(c)];
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    range = std::max(range, hi - lo);
  }
  return range;
}

// Where a pixel of image A shows a direction image B also shows: B's pixel coordinates of it
// (pixel centres at integer + 0.5), or nothing. Channels map through their cameras
// (channelToChannel); a projector would map through its warp.
using DirectionMap = std::function<std::optional<glm::dvec2>(int column, int row)>;

DirectionMap channelToChannel(const nlohmann::json& usedA, const std::string& channelA, const skyig::sky::Rgb8Image& a,
                              const nlohmann::json& usedB, const std::string& channelB, const skyig::sky::Rgb8Image& b) {
  const glm::dmat3 rayA = channelNdcToWorld(usedA, channelA);
  const glm::dmat3 toB = glm::inverse(channelNdcToWorld(usedB, channelB));
  return [=, wa = a.width, ha = a.height, wb = b.width, hb = b.height](int column, int row) -> std::optional<glm::dvec2> {
    const glm::dvec3 ndc = toB * skyig::sky::pixelRay(rayA, column, row, wa, ha);
    if (ndc.z <= 0.0) return std::nullopt;
    return glm::dvec2((ndc.x / ndc.z + 1.0) * 0.5 * wb, (1.0 - ndc.y / ndc.z) * 0.5 * hb);
  };
}

// The display values two images show for the directions they share, over any number of
// frames: every pixel of A that maps inside B (with a pixel's margin, to interpolate) and where
// B is smooth (at an edge, the horizon or the sun's disc, interpolating between two pixels says
// nothing about the direction between them).
struct SharedDirections {
  int pixels = 0, edges = 0;
  double worstLsb = 0.0, sumLsb = 0.0;
  std::vector<double> all;  // every compared value's difference, for percentiles
  double meanLsb() const { return sumLsb / std::max(1, 3 * pixels); }
  double percentileLsb(double fraction) {
    if (all.empty()) return 0.0;
    const auto at = all.begin() + static_cast<std::ptrdiff_t>(fraction * static_cast<double>(all.size() - 1));
    std::nth_element(all.begin(), at, all.end());
    return *at;
  }

  void add(const skyig::sky::Rgb8Image& a, const skyig::sky::Rgb8Image& b, const DirectionMap& toB) {
    for (int row = 0; row < a.height; ++row)
      for (int column = 0; column < a.width; ++column) {
        const std::optional<glm::dvec2> p = toB(column, row);
        if (!p || p->x < 1.0 || p->y < 1.0 || p->x > b.width - 1.0 || p->y > b.height - 1.0) continue;
        if (localRange(b, p->x, p->y) > kSmoothLsb) {
          ++edges;
          continue;
        }
        for (int c = 0; c < 3; ++c) {
          const double d = std::abs(sampleRgb8(b, p->x, p->y, c) -
                                    a.rgb[(static_cast<std::size_t>(row) * static_cast<std::size_t>(a.width) + static_cast<std::size_t>(column)) * 3 + static_cast<std::size_t>(c)]);
          worstLsb = std::max(worstLsb, d);
          sumLsb += d;
          all.push_back(d);
        }
        ++pixels;
      }
  }
};

// The host frames both nodes showed, each checked to be shown alike: what the worker derived
// from the host's state (the eye's adaptation, the tone curve's gain, the scene level, the
// attitude, position, time and sun) identical to the bit.
std::vector<std::uint32_t> expectShownAlike(const DomeNode& a, const DomeNode& b) {
  const auto shownA = a.hostFrames(), shownB = b.hostFrames();
  std::vector<std::uint32_t> common;
  for (const auto& [frame, line] : shownA)
    if (shownB.count(frame)) common.push_back(frame);
  for (std::uint32_t frame : common) {
    const auto& ua = shownA.at(frame)["used"];
    const auto& ub = shownB.at(frame)["used"];
    for (const char* key : {"adaptation_cd_m2", "adaptation_gain", "scene_cd_m2", "yaw", "pitch", "roll", "lat", "lon", "alt"})
      EXPECT_EQ(ua[key].get<double>(), ub[key].get<double>())
          << key << " at host frame " << frame << ": apart by " << ua[key].get<double>() - ub[key].get<double>();
    EXPECT_EQ(ua["utc"], ub["utc"]) << frame;
    EXPECT_EQ(shownA.at(frame)["sun"], shownB.at(frame)["sun"]) << frame;
  }
  return common;
}

// A late-afternoon time-lapse over Innsbruck (100 s of sim time per second: the eye's
// adaptation lags the dimming sky), the helicopter turning towards the sun.
constexpr const char* kPath =
    "time_s, lat, lon, alt_m, yaw, pitch, roll\n"
    "0,   47.2603, 11.3439, 900, 250, 5, 0\n"
    "3,   47.2610, 11.3400, 950, 280, 8, -10\n";

constexpr const char* kChannels = R"(
[[channel]]
name = "shared"
width = 48
height = 32
[[channel]]
name = "left"
node = "ig1"
yaw = -20.0
left = 25.0
right = 25.0
down = 15.0
up = 25.0
width = 48
height = 32
[[channel]]
name = "right"
node = "ig2"
yaw = 20.0
left = 25.0
right = 25.0
down = 15.0
up = 25.0
width = 48
height = 32
)";

}  // namespace

TEST_F(MultiNodeDome, TwoNodesShowTheSameHostFramesAlike) {
  writeConfig("[sky]\nmodel = \"preetham\"\n", kChannels);
  std::ofstream(dir_ / "path.csv") << kPath;
  ASSERT_NO_FATAL_FAILURE(startNodes({"ig1", "ig2"}));
  // 10 Hz: two sanitized nodes rendering on a loaded 2-core CI machine took 77 ms a frame (p50),
  // past a 20 Hz host's period, and fell behind it.
  constexpr int kRateHz = 10;
  constexpr double kDurationS = 3.0;
  constexpr auto kLast = static_cast<std::uint32_t>(kDurationS * kRateHz);  // host frames 0..kLast
  ASSERT_EQ(flyHost("--path " + (dir_ / "path.csv").string() + " --rate " + std::to_string(kRateHz) +
                    " --duration 3 --start-utc 2026-06-21T17:40:00Z --speed 100"),
            0)
      << hostOutput_;
  finish(kLast);
  DomeNode& a = node("ig1");
  DomeNode& b = node("ig2");

  // Each node's Start of Frame names the host frame that IG frame showed (its state dump says
  // which snapshot it drew), and in synchronous mode each host frame once, in order.
  for (DomeNode* n : {&a, &b}) {
    const auto dump = completeDumpLines(n->dump);
    std::uint32_t named = 0, previous = 0;
    for (const StartOfFrameSeen& s : n->sofs) {
      ASSERT_LT(s.igFrame, dump.size()) << n->name;
      const auto& line = dump[s.igFrame];
      if (!line["host_frame"].is_number()) continue;  // before the host spoke
      EXPECT_EQ(s.lastHostFrame, line["host_frame"].get<std::uint32_t>()) << n->name << " IG frame " << s.igFrame;
      if (named > 0) {
        EXPECT_GE(s.lastHostFrame, previous) << n->name;
      }
      previous = s.lastHostFrame;
      ++named;
    }
    EXPECT_GE(named, kLast * 3 / 4) << n->name << ": Start of Frames naming a host frame";
  }

  // The same host frames, shown alike: of kLast + 1 host frames, both nodes showed (nearly) all
  // (a worker may take two datagrams that arrive back to back as one), and for every one both
  // showed, what the worker derived from the host's state is identical to the bit.
  const auto shownA = a.hostFrames(), shownB = b.hostFrames();
  const std::vector<std::uint32_t> common = expectShownAlike(a, b);
  std::cout << "host frames shown: ig1 " << shownA.size() << ", ig2 " << shownB.size() << ", both " << common.size()
            << " of " << kLast + 1 << "\n";
  EXPECT_GE(common.size(), (kLast + 1) * 3 / 4);
  ASSERT_FALSE(common.empty());
  const double adaptationFirst = shownA.at(common.front())["used"]["adaptation_cd_m2"].get<double>();
  const double adaptationLast = shownA.at(common.back())["used"]["adaptation_cd_m2"].get<double>();
  const double sceneLast = shownA.at(common.back())["used"]["scene_cd_m2"].get<double>();
  // The adaptation moved during the flight and still lags the scene: what is compared is the
  // eye stepped in time, not a constant.
  std::cout << "adaptation " << adaptationFirst << " -> " << adaptationLast << " cd/m^2, scene " << sceneLast << "\n";
  EXPECT_NE(adaptationFirst, adaptationLast);
  EXPECT_GT(std::abs(adaptationLast / sceneLast - 1.0), 1e-3);

  // Latency: in synchronous mode a frame starts once the worker has built the host frame's
  // sky, so the datagram's arrival to the end of the frame showing it exceeds the frame's own
  // render by the worker's pick-up and build and the render thread's wake-up: under one host
  // frame (medians of each node's --stats-json, written when it stopped).
  for (DomeNode* n : {&a, &b}) {
    std::ifstream in(n->stats);
    const nlohmann::json latency = nlohmann::json::parse(in)["latency"];
    const double arrival = latency["arrival_to_frame_end"]["p50_us"].get<double>();
    const double render = latency["frame_render"]["p50_us"].get<double>();
    std::cout << n->name << ": arrival to frame end p50 " << arrival / 1000.0 << " ms, frame render p50 "
              << render / 1000.0 << " ms\n";
    EXPECT_LT(arrival - render, 1e6 / kRateHz) << n->name;
  }

  // Pixels. For host frames both showed: the channel both nodes render is the same image (its
  // dither is a function of the pixel, so within one LSB covers it), and where the left
  // channel (ig1) and the right one (ig2) overlap, the same direction has the same display
  // value within the dither of two pixels and the interpolation between them.
  int compared = 0, worstShared = 0;
  SharedDirections overlap;
  for (std::uint32_t frame : common) {
    const std::uint64_t igA = shownA.at(frame)["ig_frame"].get<std::uint64_t>();
    const std::uint64_t igB = shownB.at(frame)["ig_frame"].get<std::uint64_t>();
    const fs::path sharedA = a.savedFrame(igA, "shared", ".png"), sharedB = b.savedFrame(igB, "shared", ".png");
    ASSERT_FALSE(sharedA.empty() || sharedB.empty()) << "host frame " << frame;
    const auto pa = skyig::sky::readPngRgb8(sharedA.string(), "ig1 shared");
    const auto pb = skyig::sky::readPngRgb8(sharedB.string(), "ig2 shared");
    ASSERT_EQ(pa.rgb.size(), pb.rgb.size());
    for (std::size_t i = 0; i < pa.rgb.size(); ++i) worstShared = std::max(worstShared, std::abs(pa.rgb[i] - pb.rgb[i]));
    const auto ea = skyig::render::readExr(a.savedFrame(igA, "shared", ".exr").string());
    const auto eb = skyig::render::readExr(b.savedFrame(igB, "shared", ".exr").string());
    EXPECT_EQ(ea.attributes.at("skyig:host_frame"), eb.attributes.at("skyig:host_frame"));
    EXPECT_EQ(std::get<double>(ea.attributes.at("skyig:host_frame")), static_cast<double>(frame));
    ASSERT_EQ(ea.image.rgba.size(), eb.image.rgba.size());
    for (std::size_t i = 0; i < ea.image.rgba.size(); ++i) {
      ASSERT_NEAR(ea.image.rgba[i], eb.image.rgba[i], 1e-5f * std::abs(ea.image.rgba[i]) + 1e-9f) << "host frame " << frame;
    }

    const auto left = skyig::sky::readPngRgb8(a.savedFrame(igA, "left", ".png").string(), "ig1 left");
    const auto right = skyig::sky::readPngRgb8(b.savedFrame(igB, "right", ".png").string(), "ig2 right");
    overlap.add(left, right,
                channelToChannel(shownA.at(frame)["used"], "left", left, shownB.at(frame)["used"], "right", right));
    ++compared;
  }
  std::cout << compared << " host frames compared: shared channel differs by at most " << worstShared
            << " LSB; overlap of left (ig1) and right (ig2): " << overlap.pixels << " pixels, worst " << overlap.worstLsb
            << " LSB, mean " << overlap.meanLsb() << " LSB (" << overlap.edges << " pixels at edges left out)\n";
  EXPECT_GE(compared, static_cast<int>(common.size()));
  EXPECT_LE(worstShared, 1);
  EXPECT_GT(overlap.pixels, compared * 48 * 32 / 10);  // the frusta overlap by ~10 of 50 degrees
  EXPECT_LT(overlap.edges, overlap.pixels / 5);
  // +-1 LSB dither on each side, plus the interpolation within a cell of up to kSmoothLsb: the
  // anti-aliased horizon ramps within a pixel, where one channel's bilinear sample of its
  // box-filtered pixels and the other's own box differ by up to half the cell's range.
  EXPECT_LE(overlap.worstLsb, 2.0 + 0.5 * kSmoothLsb);
  EXPECT_LT(overlap.meanLsb(), 1.0);
}

// Two nodes driving two overlapping projectors of one dome (the generated helicopter dome of
// tests/data/calibration/dome5_small.mpcdi: ig1 the left projector, ig2 the centre one). A
// point of the dome both light shows the same sky from both: each projector's pixel, its blend
// taken out (l = ((n^gamma - beta) / ((1 - beta) alpha)), the light before blending), matches the
// other's at the same dome point within the dither, which the division by alpha enlarges.
TEST_F(MultiNodeDome, TwoNodesDriveOverlappingProjectorsAlike) {
  const std::string dome = std::string(SKYIG_SOURCE_DIR) + "/tests/data/calibration/dome5_small.mpcdi";
  writeConfig("[sky]\nmodel = \"preetham\"\n",
              "[[channel]]\nname = \"left\"\nnode = \"ig1\"\n[channel.projector]\nmpcdi = \"" + dome +
                  "\"\nregion = \"left\"\n[[channel]]\nname = \"centre\"\nnode = \"ig2\"\n[channel.projector]\nmpcdi = \"" +
                  dome + "\"\nregion = \"centre\"\n");
  std::ofstream(dir_ / "path.csv") << kPath;
  ASSERT_NO_FATAL_FAILURE(startNodes({"ig1", "ig2"}, /*answerTheHost=*/true));
  constexpr std::uint32_t kLast = 10;
  ASSERT_EQ(flyHost("--path " + (dir_ / "path.csv").string() +
                    " --rate 20 --duration 0.5 --start-utc 2026-06-21T17:40:00Z --speed 100 --lockstep 2 --lockstep-timeout 5"),
            0)
      << hostOutput_;
  finish(kLast);
  DomeNode& a = node("ig1");
  DomeNode& b = node("ig2");
  const std::vector<std::uint32_t> common = expectShownAlike(a, b);
  ASSERT_EQ(common.size(), kLast + 1);

  // The dome the fixture was made from (skyig dome --resolution 160x100): where a pixel of the
  // left projector lands on the dome, and where the centre projector shows that point.
  skyig::calibration::Dome geometryOf = skyig::calibration::defaultHelicopterDome(160, 100);
  const skyig::calibration::DomeGeometry geometry(geometryOf);
  std::size_t left = 0, centre = 0;
  for (std::size_t p = 0; p < geometryOf.projectors.size(); ++p) {
    if (geometryOf.projectors[p].name == "left") left = p;
    if (geometryOf.projectors[p].name == "centre") centre = p;
  }
  const auto calA = skyig::calibration::loadProjector(skyig::calibration::mpcdiSource(dome, "left"));
  const auto calB = skyig::calibration::loadProjector(skyig::calibration::mpcdiSource(dome, "centre"));
  constexpr float kMinAlpha = 0.25f;  // where a projector sends little, its dither says little
  const DirectionMap leftToCentre = [&](int column, int row) -> std::optional<glm::dvec2> {
    if (calA.alpha.at(column, row) < kMinAlpha) return std::nullopt;
    const auto hit = geometry.trace(left, column + 0.5, row + 0.5);
    double c = 0.0, r = 0.0;
    if (!hit.hit || !geometry.project(centre, hit.point, c, r)) return std::nullopt;
    if (c < 1.0 || r < 1.0 || c > 159.0 || r > 99.0) return std::nullopt;
    if (calB.alpha.at(static_cast<int>(c), static_cast<int>(r)) < kMinAlpha) return std::nullopt;
    return glm::dvec2(c, r);
  };
  // The projector's image with its blend taken out, back in display values.
  const auto unblend = [](skyig::sky::Rgb8Image image, const skyig::calibration::ProjectorCalibration& cal) {
    constexpr double kGamma = 2.2;  // the channels' display gamma (the default)
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const double alpha = static_cast<double>(cal.alpha.at(x, y)), beta = static_cast<double>(cal.beta.at(x, y));
        for (int c = 0; c < 3; ++c) {
          auto& v = image.rgb[(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 3 + static_cast<std::size_t>(c)];
          const double light = (std::pow(v / 255.0, kGamma) - beta) / std::max(1e-6, (1.0 - beta) * alpha);
          v = static_cast<std::uint8_t>(std::lround(std::clamp(std::pow(std::max(light, 0.0), 1.0 / kGamma), 0.0, 1.0) * 255.0));
        }
      }
    return image;
  };
  SharedDirections overlap;
  for (std::uint32_t frame : common) {
    const std::uint64_t igA = a.hostFrames().at(frame)["ig_frame"].get<std::uint64_t>();
    const std::uint64_t igB = b.hostFrames().at(frame)["ig_frame"].get<std::uint64_t>();
    const fs::path pngA = a.savedFrame(igA, "", ".png"), pngB = b.savedFrame(igB, "", ".png");  // one channel each
    ASSERT_FALSE(pngA.empty() || pngB.empty()) << "host frame " << frame;
    const auto imageA = skyig::sky::readPngRgb8(pngA.string(), "ig1 left projector");
    const auto imageB = skyig::sky::readPngRgb8(pngB.string(), "ig2 centre projector");
    ASSERT_EQ(imageA.width, 160);  // what the projector is sent, at its resolution
    ASSERT_EQ(imageB.height, 100);
    const auto exr = skyig::render::readExr(a.savedFrame(igA, "", ".exr").string());
    EXPECT_EQ(std::get<std::string>(exr.attributes.at("skyig:projector_region")), "left");
    overlap.add(unblend(imageA, calA), unblend(imageB, calB), leftToCentre);
  }
  std::cout << "overlap of the left (ig1) and centre (ig2) projectors over " << common.size() << " host frames: "
            << overlap.pixels << " pixels, worst " << overlap.worstLsb << " LSB, 99th percentile "
            << overlap.percentileLsb(0.99) << " LSB, mean " << overlap.meanLsb() << " LSB (" << overlap.edges
            << " at edges left out)\n";
  EXPECT_GT(overlap.pixels, static_cast<int>(common.size()) * 100);  // ~11 degrees of overlap, alphas over a quarter
  // The dither (+-1 LSB on each side) divided by alpha >= 1/4 in light is up to (1/alpha)^(1/gamma)
  // = 1.9 LSB of the unblended value on each side: 99% of values within 4 LSB. The few beyond
  // are where each projector's channel image, rendered at its own pixels, is resampled across
  // a gradient the smoothness filter lets through (measured: worst 9.5, 99th percentile 2.5,
  // mean 0.76 LSB).
  EXPECT_LE(overlap.percentileLsb(0.99), 4.0);
  EXPECT_LE(overlap.worstLsb, 16.0);
  EXPECT_LT(overlap.meanLsb(), 1.5);
}

// A synchronous host: `skyig host --lockstep 2` sends frame k+1 only when both nodes answered
// frame k with a Start of Frame naming it. Then no node skips or merges a host frame, whatever
// the machine's load: each shows every host frame, in order, once (the last again while the
// silent host's sync timeout expires), and alike.
TEST_F(MultiNodeDome, LockStepHostIsShownEveryFrameByEveryNode) {
  writeConfig("[sky]\nmodel = \"preetham\"\n", kChannels);
  std::ofstream(dir_ / "path.csv") << kPath;
  ASSERT_NO_FATAL_FAILURE(startNodes({"ig1", "ig2"}, /*answerTheHost=*/true));
  constexpr std::uint32_t kLast = 40;  // 2 s at 20 Hz
  ASSERT_EQ(flyHost("--path " + (dir_ / "path.csv").string() +
                    " --rate 20 --duration 2 --start-utc 2026-06-21T17:40:00Z --speed 100 --lockstep 2 --lockstep-timeout 5"),
            0)
      << hostOutput_;
  finish(kLast);
  EXPECT_NE(hostOutput_.find("host: lock step with 2 node(s): 0 frame(s) not answered by all within 5.000 s"),
            std::string::npos)
      << hostOutput_;
  for (const std::string name : {"ig1", "ig2"}) {
    std::vector<std::uint32_t> sequence;  // host frames in the order the node showed them
    for (const auto& line : completeDumpLines(node(name).dump))
      if (line["host_frame"].is_number()) sequence.push_back(line["host_frame"].get<std::uint32_t>());
    ASSERT_GE(sequence.size(), kLast + 1) << name;
    for (std::uint32_t k = 0; k <= kLast; ++k) EXPECT_EQ(sequence[k], k) << name;
    for (std::size_t i = kLast + 1; i < sequence.size(); ++i) EXPECT_EQ(sequence[i], kLast) << name;
  }
  EXPECT_EQ(expectShownAlike(node("ig1"), node("ig2")).size(), kLast + 1);
}

// Clouds are a function of the host's state and clock: two nodes fed one stream under a broken
// cumulus deck in a 10 m/s westerly show the same clouds in every host frame (the same EXR
// within float rounding, the same PNG within the dither), the wind moves them between host
// frames, and two replays of a node's recording write the same bytes, which are the live
// node's clouds.
TEST_F(MultiNodeDome, TwoNodesAndAReplayShowTheSameCloudsMovedByTheHostsWind) {
  writeConfig("[sky]\nmodel = \"physical\"\natmosphere_tables = \"small\"\natmosphere_cache = \"" +
                  std::string(SKYIG_BINARY_DIR) + "/atmosphere-test-cache/skyig\"\n"
                  // the host's visibility (skyig host's default): its tables are the node's own
                  "[atmosphere]\nvisibility_km = 40.0\n",
              "[[channel]]\nname = \"up\"\npitch = 45.0\nleft = 40.0\nright = 40.0\ndown = 25.0\nup = 25.0\n"
              "width = 64\nheight = 40\n");
  // A hover over Innsbruck, facing east into the morning sun's side of the sky.
  std::ofstream(dir_ / "path.csv") << "time_s, lat, lon, alt_m, yaw, pitch, roll\n0, 47.2603, 11.3439, 620, 90, 0, 0\n"
                                      "3, 47.2603, 11.3439, 620, 90, 0, 0\n";
  record_ = true;
  ASSERT_NO_FATAL_FAILURE(startNodes({"ig1", "ig2"}, /*answerTheHost=*/true));
  constexpr std::uint32_t kLast = 30;  // 3 s at 10 Hz, 20 times as fast: 60 s of host time
  ASSERT_EQ(flyHost("--path " + (dir_ / "path.csv").string() +
                    " --rate 10 --duration 3 --start-utc 2026-06-21T09:00:00Z --speed 20 --lockstep 2 "
                    "--lockstep-timeout 20 --cloud cumulus:1200:800:50:10:270"),
            0)
      << hostOutput_;
  finish(kLast);
  DomeNode& a = node("ig1");
  DomeNode& b = node("ig2");
  const auto shownA = a.hostFrames(), shownB = b.hostFrames();
  // In lock step each node shows every host frame; on a loaded machine a frame may pass the
  // host's timeout, so the comparison is over the frames both showed (nearly all).
  const std::vector<std::uint32_t> common = expectShownAlike(a, b);
  EXPECT_GE(common.size(), (kLast + 1) * 3 / 4);
  ASSERT_GE(common.size(), 2u);

  auto exrOf = [](const DomeNode& n, const nlohmann::json& line) {
    return skyig::render::readExr(n.savedFrame(line["ig_frame"].get<std::uint64_t>(), "", ".exr").string());
  };
  // The mean relative difference of two frames' luminance (channel G stands for it here).
  auto meanRelative = [](const skyig::render::ExrFile& x, const skyig::render::ExrFile& y) {
    double sum = 0.0;
    for (std::size_t i = 1; i < x.image.rgba.size(); i += 4) {
      const double u = x.image.rgba[i], v = y.image.rgba[i];
      sum += std::abs(u - v) / (std::abs(v) + 1e-3);
    }
    return sum / static_cast<double>(x.image.rgba.size() / 4);
  };
  for (std::uint32_t frame : common) {
    const auto ea = exrOf(a, shownA.at(frame)), eb = exrOf(b, shownB.at(frame));
    ASSERT_EQ(ea.image.rgba.size(), eb.image.rgba.size());
    for (std::size_t i = 0; i < ea.image.rgba.size(); ++i)
      ASSERT_NEAR(ea.image.rgba[i], eb.image.rgba[i], 1e-5f * std::abs(ea.image.rgba[i]) + 1e-9f) << "host frame " << frame;
    const auto pa = skyig::sky::readPngRgb8(a.savedFrame(shownA.at(frame)["ig_frame"].get<std::uint64_t>(), "", ".png").string(), "ig1");
    const auto pb = skyig::sky::readPngRgb8(b.savedFrame(shownB.at(frame)["ig_frame"].get<std::uint64_t>(), "", ".png").string(), "ig2");
    ASSERT_EQ(pa.rgb.size(), pb.rgb.size());
    for (std::size_t i = 0; i < pa.rgb.size(); ++i) ASSERT_LE(std::abs(pa.rgb[i] - pb.rgb[i]), 1) << "host frame " << frame;
  }
  const auto first = exrOf(a, shownA.at(common.front())), last = exrOf(a, shownA.at(common.back()));
  EXPECT_EQ(std::get<std::string>(first.attributes.at("skyig:cloud_layer_1")), "cumulus base 1200 m, 800 m thick, 50 % cover, severity 2");
  // 60 s of a 10 m/s wind move the field 600 m, over half a cumulus cell: the broken deck's
  // pattern changes (the sun moves 0.25 deg meanwhile, which alone changes the sky by well
  // under 1 %).
  const double moved = meanRelative(last, first);
  std::cout << "clouds between host frames " << common.front() << " and " << common.back() << ": mean luminance change "
            << 100.0 * moved << " %\n";
  ASSERT_GE(common.back() - common.front(), kLast / 2);
  EXPECT_GT(moved, 0.05);

  // Two replays of ig1's recording: the same bytes, and the live node's clouds (its EXR for the
  // same host frame, within float rounding).
  auto replay = [&](const std::string& out) {
    const std::string command = std::string(SKYIG_EXECUTABLE) + " replay " + a.recording.string() + " --config " +
                                (dir_ / "dome.toml").string() + " --quiet --exr --out " + (dir_ / out).string() +
                                " --dump-state " + (dir_ / (out + ".jsonl")).string() + " >" +
                                (dir_ / (out + ".log")).string() + " 2>&1";
    return std::system(command.c_str());
  };
  ASSERT_EQ(replay("replay1"), 0) << slurp(dir_ / "replay1.log");
  ASSERT_EQ(replay("replay2"), 0) << slurp(dir_ / "replay2.log");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "replay1")) {
    EXPECT_EQ(slurp(e.path()), slurp(dir_ / "replay2" / e.path().filename())) << e.path().filename();
    ++files;
  }
  EXPECT_GT(files, static_cast<int>(kLast));
  int matched = 0;
  for (const auto& line : completeDumpLines(dir_ / "replay1.jsonl")) {
    if (!line["host_frame"].is_number()) continue;
    const auto frame = line["host_frame"].get<std::uint32_t>();
    // At the host's instant (before the host's second frame the replay's clock runs at the
    // recording's pace, not yet the host's).
    if (!shownA.count(frame) || line["used"]["utc"] != shownA.at(frame)["used"]["utc"]) continue;
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "frame_%06llu_", static_cast<unsigned long long>(line["ig_frame"].get<std::uint64_t>()));
    for (const auto& e : fs::directory_iterator(dir_ / "replay1"))
      if (e.path().filename().string().rfind(prefix, 0) == 0 && e.path().extension() == ".exr") {
        const auto replayed = skyig::render::readExr(e.path().string()), live = exrOf(a, shownA.at(frame));
        ASSERT_EQ(replayed.image.rgba.size(), live.image.rgba.size());
        for (std::size_t i = 0; i < live.image.rgba.size(); ++i)
          ASSERT_NEAR(replayed.image.rgba[i], live.image.rgba[i], 1e-5f * std::abs(live.image.rgba[i]) + 1e-9f)
              << "host frame " << frame;
        ++matched;
      }
  }
  std::cout << files << " replayed files identical twice; " << matched << " replayed frames against the live node's\n";
  EXPECT_GT(matched, static_cast<int>(kLast / 2));
}

// The worker of a synchronous node builds states only at host instants: a silent host gets no
// state at the local clock (the dome holds host frame N, it does not drift on each node's own
// time), and new tables rebuild the last host frame's instant. A free-running node's worker
// follows its local clock while the host is silent, so the sun moves on.
TEST(SynchronousWorker, BuildsOnlyAtHostInstants) {
  const fs::path dir = freshTestDirectory("skyig_sync_worker_");
  std::ofstream(dir / "node.toml") << "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\nwidth = 32\nheight = 24\n";
  NodeConfig config = loadNodeConfig((dir / "node.toml").string());
  loadSkyData(config);
  NodeStats stats;
  HostSnapshot host;
  const Clock::time_point t0 = Clock::now();
  host.state.updates = 1;
  host.state.received = t0;
  host.state.timeValid = true;
  host.state.utc = {2026, 6, 21, 17 * 3600.0 + 40 * 60.0};
  host.state.utcTime = t0;
  host.state.ownshipValid = true;
  host.state.ownship = {47.26, 11.34, 900.0, {270.0, 5.0, 0.0}};

  SkyWorker sync(config, nullptr, stats);
  sync.setHostInstantsOnly(true);
  const auto first = sync.step(&host, t0 + 5ms);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->observer.utc.secondsOfDay, host.state.utc.secondsOfDay);  // at the host's instant
  EXPECT_FALSE(sync.step(&host, t0 + 500ms).has_value());                   // silent: nothing new
  const auto rebuilt = sync.step(&host, t0 + 500ms, /*force=*/true);       // new tables
  ASSERT_TRUE(rebuilt.has_value());
  EXPECT_EQ(rebuilt->observer.utc.secondsOfDay, first->observer.utc.secondsOfDay);
  EXPECT_EQ(rebuilt->sunAltitude, first->sunAltitude);

  SkyWorker freeRunning(config, nullptr, stats);
  ASSERT_TRUE(freeRunning.step(&host, t0 + 5ms).has_value());
  const auto later = freeRunning.step(&host, t0 + 500ms);
  ASSERT_TRUE(later.has_value());
  EXPECT_NEAR(later->observer.utc.secondsOfDay - first->observer.utc.secondsOfDay, 0.5, 1e-6);
  fs::remove_all(dir);
}

// The eye integrates the scene at every host message, also at those a busy node's worker
// skipped (it reads only the latest snapshot and steps through the ones published before it):
// a worker that saw every fourth message of a darkening dusk adapts exactly as one that saw
// them all. Without the catch-up the two differ by far more than the last bit.
TEST(SynchronousWorker, SkippedHostMessagesStepTheEyeAlike) {
  const fs::path dir = freshTestDirectory("skyig_skipped_messages_");
  std::ofstream(dir / "node.toml") << "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\nwidth = 32\nheight = 24\n";
  NodeConfig config = loadNodeConfig((dir / "node.toml").string());
  loadSkyData(config);
  ASSERT_TRUE(config.temporalAdaptation);
  NodeStats stats;
  Latest<HostSnapshot> latest;
  HostPublisher publisher(latest);
  SkyWorker everyMessage(config, nullptr, stats), everyFourth(config, nullptr, stats);
  everyMessage.setHostInstantsOnly(true);
  everyFourth.setHostInstantsOnly(true);

  const Clock::time_point t0 = Clock::now();
  HostState state;
  state.timeValid = true;
  state.ownshipValid = true;
  state.ownship = {47.26, 11.34, 900.0, {90.0, 5.0, 0.0}};
  std::optional<skyig::sky::SkyState> all, some;
  for (int k = 1; k <= 41; ++k) {
    // A minute of dusk per message, 100 ms apart: the scene darkens faster than the eye follows.
    state.updates = static_cast<std::uint64_t>(k);
    state.received = state.utcTime = t0 + k * 100ms;
    state.utc = {2026, 6, 21, 19 * 3600.0 + k * 60.0};
    publisher.publish(HostSnapshot{state, OwnshipPredictor{}, std::nullopt, std::nullopt, state.received, {}});
    const auto host = latest.get();
    all = everyMessage.step(host.get(), state.received);
    ASSERT_TRUE(all.has_value());
    if (k % 4 == 1) some = everyFourth.step(host.get(), state.received);
  }
  ASSERT_TRUE(some.has_value());
  EXPECT_EQ(some->observer.utc.secondsOfDay, all->observer.utc.secondsOfDay);
  EXPECT_GT(all->worldAdaptationLuminance / all->sceneLuminance, 1.05);  // the eye lags the dusk
  EXPECT_EQ(some->worldAdaptationLuminance, all->worldAdaptationLuminance);
  EXPECT_EQ(some->adaptationGain, all->adaptationGain);
  fs::remove_all(dir);
}

// The history a snapshot carries is bounded: a reader stalled for long holds kHistory bare
// snapshots, not the whole stream.
TEST(HostPublisher, EachSnapshotCarriesTheLastOnesBeforeIt) {
  Latest<HostSnapshot> latest;
  HostPublisher publisher(latest);
  for (std::uint64_t k = 1; k <= HostPublisher::kHistory + 10; ++k) {
    HostSnapshot s;
    s.state.updates = k;
    publisher.publish(s);
  }
  const auto last = latest.get();
  ASSERT_EQ(last->earlier.size(), HostPublisher::kHistory);
  EXPECT_EQ(last->earlier.front()->state.updates, 10u);
  EXPECT_EQ(last->earlier.back()->state.updates, HostPublisher::kHistory + 9);
  for (const auto& e : last->earlier) EXPECT_TRUE(e->earlier.empty());
}
