// Record and replay (docs/record-replay.md): a live session recorded and replayed gives the
// same host states; replays are byte-identical; CAN logs replay through the CANaerospace
// decoder; bad files give clear errors naming the record and offset, and --skip-bad counts what
// it skips.
#include "protocol/canaerospace/state_encoder.h"
#include "protocol/candump/candump.h"
#include "protocol/cigi/encoder.h"
#include "protocol/io/byte_sink.h"
#include "node/node.h"
#include "node/record/recorder.h"

#include "tests/node/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <cstdlib>
#include <functional>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

using namespace skyig::services;
using namespace skyig::services::testing;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

namespace {

// A node of one 16 x 16 analytic-sky channel listening on loopback `port`, for the recording.
NodeOptions tinyRecordingNode(std::uint16_t port) {
  NodeOptions o;
  o.config.sky.model = skyig::sky::SkyModel::Preetham;
  o.config.channels.front().width = 16;
  o.config.channels.front().height = 16;
  o.listen = {"127.0.0.1", port};
  return o;
}

const std::string kRecording = std::string(SKYIG_SOURCE_DIR) + "/tests/data/circuit_timelapse.pcap";

class RecordReplay : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = freshTestDirectory("skyig_rr_");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Replays render the analytic sky (what the record/replay checks need, without tables); a
  // physical sky would keep its tables in the build tree.
  SkyigResult skyig(const std::string& args) const {
    const fs::path analytic = dir_ / "analytic.toml";
    std::ofstream(analytic) << "[sky]\nmodel = \"preetham\"\n";
    return runSkyig(args + (args.rfind("replay ", 0) == 0 ? " --config " + analytic.string() : ""), dir_);
  }

  // A copy of the fixture with `edit` applied to its bytes.
  fs::path corrupted(const std::string& name, const std::function<void(std::string&)>& edit) const {
    std::string bytes = slurp(kRecording);
    edit(bytes);
    std::ofstream(dir_ / name, std::ios::binary) << bytes;
    return dir_ / name;
  }

  fs::path dir_;
};


}  // namespace

// serve --record during a live session, then replay the recording: every host frame both
// dumps show carries the same host values.
TEST_F(RecordReplay, ReplayGivesTheLiveRunsHostStates) {
  const std::uint16_t port = freeLoopbackPort();
  NodeOptions o;
  o.config.sky.model = skyig::sky::SkyModel::Preetham;  // the analytic sky: no tables to load
  o.config.channels.front().width = 32;
  o.config.channels.front().height = 24;
  o.listen = {"127.0.0.1", port};
  o.dumpStatePath = (dir_ / "live.jsonl").string();
  o.recordPath = (dir_ / "live.pcap").string();
  NodeStats stats;
  std::atomic<bool> stop{false};
  StoppedThread node(stop, [&] { runNode(o, stats, stop); });
  ASSERT_TRUE(waitForFirstFrame(stats.frames));  // the socket is bound
  const std::string host = std::string(SKYIG_EXECUTABLE) + " host --path " + SKYIG_SOURCE_DIR +
                           "/config/circuit.csv --rate 30 --duration 1.5 --speed 30 --to 127.0.0.1:" + std::to_string(port) + " >/dev/null";
  EXPECT_EQ(std::system(host.c_str()), 0);
  EXPECT_TRUE(waitForFrames(stats.frames, 3));  // the last datagrams are drawn and dumped
  stop = true;
  node.join();
  EXPECT_EQ(stats.recorded.load(), stats.datagrams.load());

  const SkyigResult r = skyig("replay " + (dir_ / "live.pcap").string() + " --quiet --size 32x24 --dump-state " + (dir_ / "replay.jsonl").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::map<long, nlohmann::json> live, replayed;
  for (const auto& l : readStateDump(dir_ / "live.jsonl"))
    if (!l["host_frame"].is_null()) live[l["host_frame"].get<long>()] = l["host"];
  for (const auto& l : readStateDump(dir_ / "replay.jsonl"))
    if (!l["host_frame"].is_null()) replayed[l["host_frame"].get<long>()] = l["host"];
  int compared = 0;
  for (const auto& [frame, hostValues] : replayed) {
    const auto it = live.find(frame);
    if (it == live.end()) continue;
    for (const char* key : {"lat", "lon", "alt", "yaw", "pitch", "roll", "visibility_m"})
      EXPECT_EQ(hostValues[key], it->second[key]) << "host frame " << frame << " " << key;
    // The sim clock is refined from the recorded timestamps, not this machine's timing.
    EXPECT_EQ(hostValues["utc"].get<std::string>().substr(0, 16), it->second["utc"].get<std::string>().substr(0, 16));
    ++compared;
  }
  EXPECT_GT(compared, 30);
}

// Two replays of one recording write the same bytes, and a replay that writes every 30th frame
// draws only those (4 of 91 frames) yet writes each, EXR and PNG, byte for byte as the replay
// writing every frame does: the worker still steps at every host message (the eye, the clock),
// and each frame not drawn still advances the renderer's upload of the tables the recording's
// visibility changes to (without that, frame 30 on showed the old tables longer).
TEST_F(RecordReplay, AReplayDrawsOnlyTheFramesItWritesByteForByteAsAnEveryFrameReplay) {
  std::map<std::string, std::string> summary;
  for (const auto& [out, every] : {std::pair{"a", 30}, {"b", 30}, {"all", 1}}) {
    const SkyigResult r = skyig("replay " + kRecording + " --quiet --size 64x48 --to 90 --every " + std::to_string(every) +
                                " --exr --png --out " + (dir_ / out).string());
    ASSERT_EQ(r.exitCode, 0) << r.err;
    summary[out] = r.out;
  }
  // Frames 0-90 and the 92nd, computed to find it past --to.
  EXPECT_NE(summary["a"].find(": 92 frames (4 drawn), 8 images"), std::string::npos) << summary["a"];
  EXPECT_NE(summary["all"].find(": 92 frames (91 drawn), 182 images"), std::string::npos) << summary["all"];
  int compared = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "a")) {
    EXPECT_EQ(slurp(e.path()), slurp(dir_ / "b" / e.path().filename())) << e.path().filename();
    EXPECT_EQ(slurp(e.path()), slurp(dir_ / "all" / e.path().filename())) << e.path().filename();
    ++compared;
  }
  EXPECT_EQ(compared, 8);  // frames 0, 30, 60, 90, EXR and PNG
  // Named by frame number and the sim time it shows. Frame 30 is 1 s into the recording and
  // shows the state of the host's last message (0.95 s, timestamp 85.5 s of a 90x time-lapse
  // from 18:30), at that message's own instant, as the node does.
  EXPECT_TRUE(fs::exists(dir_ / "a" / "frame_000030_2026-06-21T18-31-25.500Z.exr"));
}

TEST_F(RecordReplay, FromAndToSelectAPart) {
  const SkyigResult r = skyig("replay " + kRecording + " --quiet --size 32x24 --from 2026-06-21T18:45:00Z --to 2026-06-21T18:46:00Z --png --out " +
                      (dir_ / "part").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  int frames = 0;
  for (const auto& e : fs::directory_iterator(dir_ / "part")) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(name.find("T18-45-") != std::string::npos || name.find("T18-46-00.000") != std::string::npos) << name;
    ++frames;
  }
  EXPECT_NEAR(frames, 20, 2);  // one sim minute = 2/3 s of recording at 30 frames/s
}

TEST_F(RecordReplay, CandumpLogReplaysThroughTheCanAerospaceDecoder) {
  skyig::protocol::canaerospace::CanAerospaceState s;
  s.latitudeDeg = -33.9461;
  s.longitudeDeg = 151.1772;
  s.altitudeM = 21.0;
  s.headingDeg = 160.0;
  s.pitchDeg = 3.0;
  s.rollDeg = 1.5;
  s.hour = 9;
  s.minute = 41;
  s.second = 5;
  s.year = 2026;
  s.month = 11;
  s.day = 22;
  skyig::protocol::canaerospace::StateEncoder encoder;
  skyig::protocol::io::MemorySink sink;
  skyig::protocol::candump::Writer writer(sink);
  std::int64_t t = 1790000000000000;
  for (int repeat = 0; repeat < 3; ++repeat)
    for (const auto& f : encoder.encode(s)) writer.write(t += 2000, "can0", f);
  std::ofstream(dir_ / "flight.log", std::ios::binary).write(reinterpret_cast<const char*>(sink.data.data()),
                                                             static_cast<std::streamsize>(sink.data.size()));
  const SkyigResult r = skyig("replay " + (dir_ / "flight.log").string() + " --quiet --size 32x24 --dump-state " + (dir_ / "can.jsonl").string());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto lines = readStateDump(dir_ / "can.jsonl");
  ASSERT_FALSE(lines.empty());
  // The first frame already shows the host's place and time: each parameter comes in a CAN frame
  // of its own, and the first record (a latitude alone) is no pose to show yet.
  const auto& first = lines.front();
  EXPECT_NEAR(first["used"]["lat"].get<double>(), -33.9461, 1e-9);
  EXPECT_NEAR(first["used"]["lon"].get<double>(), 151.1772, 1e-9);
  EXPECT_EQ(first["used"]["utc"].get<std::string>().substr(0, 19), "2026-11-22T09:41:05");
  const auto& last = lines.back();
  EXPECT_NEAR(last["used"]["lat"].get<double>(), -33.9461, 1e-9);
  EXPECT_NEAR(last["used"]["lon"].get<double>(), 151.1772, 1e-9);
  EXPECT_NEAR(last["used"]["yaw"].get<double>(), 160.0, 1e-4);
  EXPECT_EQ(last["used"]["utc"].get<std::string>().substr(0, 19), "2026-11-22T09:41:05");
}

TEST_F(RecordReplay, TruncatedPcapNamesTheRecordAndOffset) {
  const fs::path cut = corrupted("cut.pcap", [](std::string& b) { b.resize(b.size() - 70); });
  const SkyigResult r = skyig("replay " + cut.string() + " --quiet --size 16x16 --frame-rate 2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("record 801"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("at byte 168024"), std::string::npos) << r.err;
  const SkyigResult skipping = skyig("replay " + cut.string() + " --quiet --size 16x16 --frame-rate 2 --skip-bad");
  EXPECT_EQ(skipping.exitCode, 0) << skipping.err;
  EXPECT_NE(skipping.out.find("skipped 1 bad records"), std::string::npos) << skipping.out;
}

TEST_F(RecordReplay, CorruptRecordInTheMiddle) {
  // Record 400's captured length (4 bytes at its header + 8) set absurd.
  const fs::path bad = corrupted("bad.pcap", [](std::string& b) {
    const std::size_t recordSize = (b.size() - 24) / 801;  // every record has the same size here
    const std::size_t header = 24 + 399 * recordSize;
    b[header + 8] = '\xff';
    b[header + 9] = '\xff';
    b[header + 10] = '\xff';
    b[header + 11] = '\x7f';
  });
  const SkyigResult r = skyig("replay " + bad.string() + " --quiet --size 16x16 --frame-rate 2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("record 400"), std::string::npos) << r.err;
  const SkyigResult skipping = skyig("replay " + bad.string() + " --quiet --size 16x16 --frame-rate 2 --skip-bad");
  EXPECT_EQ(skipping.exitCode, 0) << skipping.err;
  EXPECT_NE(skipping.out.find("replayed 800 host messages"), std::string::npos) << skipping.out;
  EXPECT_NE(skipping.out.find("skipped 1 bad records"), std::string::npos) << skipping.out;
}

TEST_F(RecordReplay, UnparseableCandumpLineAndNotARecording) {
  std::ofstream(dir_ / "bad.log") << "(1790000000.000000) can0 137#0000000000000000\n(1790000000.1) can0 nonsense\n";
  const SkyigResult r = skyig("replay " + (dir_ / "bad.log").string() + " --quiet --size 32x24");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("line 2"), std::string::npos) << r.err;
  std::ofstream(dir_ / "picture.png") << "\x89PNG\r\n\x1a\n0000000000000000";
  const SkyigResult n = skyig("replay " + (dir_ / "picture.png").string() + " --quiet");
  EXPECT_EQ(n.exitCode, 2);
  EXPECT_NE(n.err.find("not a recording"), std::string::npos) << n.err;
}

// A full disk stops the recording with an error; the node keeps rendering.
TEST_F(RecordReplay, FullDiskStopsRecordingNotTheNode) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  const std::uint16_t port = freeLoopbackPort();
  NodeOptions o = tinyRecordingNode(port);
  o.recordPath = "/dev/full";
  NodeStats stats;
  std::atomic<bool> stop{false};
  StoppedThread node(stop, [&] {
    try {
      runNode(o, stats, stop);
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  });
  ASSERT_TRUE(waitForFirstFrame(stats.frames));  // the socket is bound
  const std::string host = std::string(SKYIG_EXECUTABLE) + " host --path " + SKYIG_SOURCE_DIR +
                           "/config/circuit.csv --rate 30 --duration 0.5 --to 127.0.0.1:" + std::to_string(port) + " >/dev/null";
  EXPECT_EQ(std::system(host.c_str()), 0);
  const std::uint64_t frames = stats.frames.load();
  EXPECT_TRUE(waitForFrames(stats.frames, 6));  // still rendering after the recording died
  stop = true;
  node.join();
  EXPECT_EQ(stats.recordErrors.load(), 1u);
  EXPECT_GT(stats.datagrams.load(), 10u);
  EXPECT_GT(stats.frames.load(), frames + 5);  // still rendering after the recording died
}

TEST_F(RecordReplay, TcpdumpReadsWhatSkyigRecorded) {
  if (std::system("command -v tcpdump >/dev/null 2>&1") != 0) GTEST_SKIP() << "tcpdump is not installed";
  const std::string cmd = "tcpdump -nr " + kRecording + " 2>/dev/null | grep -c 'UDP, length 152' > " + (dir_ / "n.txt").string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_EQ(std::stoi(slurp(dir_ / "n.txt")), 801);
}

// --send re-transmits the recording's datagrams, unchanged, to a live IG instead of rendering.
TEST_F(RecordReplay, SendRetransmitsTheRecording) {
  UdpSocket ig({"127.0.0.1", 0});
  const std::string to = "127.0.0.1:" + std::to_string(ig.localEndpoint().port);
  std::thread replayer([&] { skyig("replay " + kRecording + " --quiet --send " + to); });
  std::array<std::uint8_t, 2048> buffer{};
  sockaddr_in from{};
  std::size_t received = 0, bytes = 0;
  while (const std::size_t n = ig.receive(buffer, from, 2000ms)) {
    ++received;
    bytes += n;
  }
  replayer.join();
  EXPECT_EQ(received, 801u);
  EXPECT_EQ(bytes, 801u * 152u);
}

// Each recording defect of tests/data (make_defect_recordings.py) and what skyig does with it.
namespace {
std::string defect(const std::string& name) { return std::string(SKYIG_SOURCE_DIR) + "/tests/data/" + name; }

// A CIGI datagram as big as UDP over IPv4 carries: an IG Control and View Controls.
std::vector<std::uint8_t> largestDatagram() {
  namespace cigi = skyig::protocol::cigi;
  std::vector<cigi::Packet> packets{cigi::IgControl{}};
  while (packets.size() < 2047) packets.push_back(cigi::ViewControl{});
  std::vector<std::uint8_t> bytes;
  EXPECT_EQ(cigi::encodeMessage(packets, skyig::protocol::ByteOrder::big, bytes), "");
  return bytes;
}
}  // namespace

// A 65,496-byte datagram exceeded the old 65,535-byte snap length with its headers and ended
// the recording; now serve --record keeps it whole and goes on.
TEST_F(RecordReplay, ServeRecordsTheLargestDatagramWhole) {
  const std::uint16_t port = freeLoopbackPort();
  NodeOptions o = tinyRecordingNode(port);
  o.recordPath = (dir_ / "big.pcap").string();
  NodeStats stats;
  std::atomic<bool> stop{false};
  StoppedThread node(stop, [&] { runNode(o, stats, stop); });
  ASSERT_TRUE(waitForFirstFrame(stats.frames));
  UdpSocket host({"127.0.0.1", 0});
  const std::vector<std::uint8_t> big = largestDatagram();
  ASSERT_GT(big.size(), 65494u);
  for (int i = 0; i < 3; ++i) host.sendTo(big, toSockaddr({"127.0.0.1", port}));
  EXPECT_TRUE(waitUntil([&] { return stats.datagrams.load() >= 3; }));
  stop = true;
  node.join();
  EXPECT_EQ(stats.recordErrors.load(), 0u);
  EXPECT_EQ(stats.recorded.load(), 3u);
  const SkyigResult r = skyig("replay " + (dir_ / "big.pcap").string() + " --quiet --size 16x16");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("replayed 3 host messages"), std::string::npos) << r.out;
}

TEST_F(RecordReplay, RecordKeepsTheLargestDatagramWhole) {
  const std::uint16_t port = freeLoopbackPort();
  const fs::path out = dir_ / "big.pcap";
  std::thread recorder([&] {
    EXPECT_EQ(std::system((std::string(SKYIG_EXECUTABLE) + " record --listen 127.0.0.1:" + std::to_string(port) +
                           " --out " + out.string() + " --count 2 --duration 20 2>/dev/null >/dev/null").c_str()), 0);
  });
  UdpSocket host({"127.0.0.1", 0});
  const std::vector<std::uint8_t> big = largestDatagram();
  // Until the recorder has both (it binds a moment after starting).
  const auto end = std::chrono::steady_clock::now() + 20s;
  while (std::chrono::steady_clock::now() < end && !(fs::exists(out) && fs::file_size(out) >= 24 + 2 * (16 + 42 + big.size()))) {
    host.sendTo(big, toSockaddr({"127.0.0.1", port}));
    std::this_thread::sleep_for(100ms);
  }
  recorder.join();
  const SkyigResult r = skyig("replay " + out.string() + " --quiet --size 16x16");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("replayed 2 host messages"), std::string::npos) << r.out;
}

TEST_F(RecordReplay, LargeDatagramRecordingReplays) {
  const SkyigResult r = skyig("replay " + defect("large_datagram.pcap") + " --quiet --size 16x16");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("replayed 11 host messages"), std::string::npos) << r.out;
}

// A timestamp 1e6 s ahead used to be rendered at 30 frames a second of recording time (30
// million frames); the pause is skipped and said so.
TEST_F(RecordReplay, MillionSecondGapIsSkippedInSeconds) {
  const auto start = std::chrono::steady_clock::now();
  const SkyigResult r = skyig("replay " + defect("time_gap.pcap") + " --quiet --size 16x16");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_LT(seconds, 60.0);
  EXPECT_NE(r.out.find("replayed 40 host messages: 60 frames"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("skipped 1 pauses longer than --max-gap 60 s (1000000.000 s"), std::string::npos) << r.out;
  EXPECT_NE((r.out + r.err).find("after record 20"), std::string::npos) << r.out << r.err;  // the log's warning
}

TEST_F(RecordReplay, SkipBadResynchronisesWhenTheFirstRecordIsCorrupt) {
  const SkyigResult strict = skyig("replay " + defect("corrupt_first_record.pcap") + " --quiet --size 16x16");
  EXPECT_EQ(strict.exitCode, 2);
  EXPECT_NE(strict.err.find("record 1 at byte 24"), std::string::npos) << strict.err;
  const SkyigResult r = skyig("replay " + defect("corrupt_first_record.pcap") + " --quiet --size 16x16 --skip-bad");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("replayed 39 host messages"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("skipped 1 bad records"), std::string::npos) << r.out;
}

TEST_F(RecordReplay, UnknownLinkTypeExitsTwoAndSaysWhich) {
  for (const char* extra : {"", " --skip-bad", " --send 127.0.0.1:9"}) {
    const SkyigResult r = skyig("replay " + defect("unknown_link_type.pcap") + " --quiet --size 16x16" + extra);
    EXPECT_EQ(r.exitCode, 2) << extra;
    EXPECT_NE(r.err.find("pcap link type 147 is not supported"), std::string::npos) << r.err;
  }
}

TEST_F(RecordReplay, SendToPortZeroExitsTwo) {
  const SkyigResult r = skyig("replay " + kRecording + " --quiet --send 127.0.0.1:0");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--send: port 0"), std::string::npos) << r.err;
}

// A FIFO fed by another thread is read as a stream, once, front to back.
TEST_F(RecordReplay, ReplayReadsAFifoAsAStream) {
  const fs::path fifo = dir_ / "host.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::signal(SIGPIPE, SIG_IGN);  // a replay that stopped reading must fail the test, not kill it
  std::thread feeder([&] {
    const std::string bytes = slurp(kRecording);
    int fd = -1;
    const auto end = std::chrono::steady_clock::now() + 30s;  // until the replay opens it
    while ((fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK)) < 0 && std::chrono::steady_clock::now() < end)
      std::this_thread::sleep_for(10ms);
    ASSERT_GE(fd, 0) << "the replay never opened the FIFO";
    ::fcntl(fd, F_SETFL, 0);  // blocking writes from here on
    for (std::size_t done = 0; done < bytes.size();) {
      const ssize_t n = ::write(fd, bytes.data() + done, std::min<std::size_t>(4096, bytes.size() - done));
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
  });
  const SkyigResult r = skyig("replay " + fifo.string() + " --quiet --size 16x16 --frame-rate 2");
  feeder.join();
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("replayed 801 host messages"), std::string::npos) << r.out;
}
