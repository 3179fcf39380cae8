// Host sessions, the host's clock and ownship prediction without a network: who may drive the
// node, when a host has restarted, what is stale, how timestamps unwrap, and that prediction
// stays on the host's path and inside the ranges of a pose.
#include "protocol/cigi/date.h"
#include "protocol/cigi/encoder.h"
#include "node/transport/cigi_receiver.h"
#include "node/host/cigi_state.h"
#include "node/host/host_session.h"
#include "node/host/ownship_predictor.h"

#include <gtest/gtest.h>

#include <arpa/inet.h>

#include <cmath>

using namespace skyig::services;
namespace cigi = skyig::protocol::cigi;
using namespace std::chrono_literals;

namespace {

Sender address(const char* ip, std::uint16_t port) { return toSender(toSockaddr(Endpoint{ip, port})); }

cigi::IgControl frame(std::uint32_t n, std::optional<std::uint32_t> timestamp = std::nullopt) {
  cigi::IgControl ig;
  ig.hostFrameNumber = n;
  ig.timestampValid = timestamp.has_value();
  ig.timestamp = timestamp.value_or(0);
  return ig;
}

std::uint32_t ticks(double seconds) { return static_cast<std::uint32_t>(std::llround(seconds * 1e5)); }

}  // namespace

// The host modules read addresses without the socket headers (node/host/sender.h): the same
// answers as the kernel's reader, inet_pton(AF_INET), for good addresses and bad ones.
TEST(Sender, ReadsDottedQuadsAsInetPtonDoes) {
  for (const char* text : {"127.0.0.1", "0.0.0.0", "255.255.255.255", "10.1.2.3", "192.168.0.1", "1.2.3", "1.2.3.4.5",
                           "256.1.1.1", "01.2.3.4", "1.2.3.04", "1..2.3", "1.2.3.4 ", " 1.2.3.4", "a.b.c.d", "",
                           "1.2.3.", "1234.1.1.1", "1.2.3.4/8", "-1.2.3.4"}) {
    in_addr kernel{};
    const bool kernelReads = inet_pton(AF_INET, text, &kernel) == 1;
    const std::optional<std::uint32_t> ours = parseIpv4(text);
    EXPECT_EQ(ours.has_value(), kernelReads) << '"' << text << '"';
    if (ours && kernelReads) {
      EXPECT_EQ(*ours, ntohl(kernel.s_addr)) << text;
      EXPECT_EQ(ipv4ToString(*ours), text);
    }
  }
  EXPECT_EQ((Sender{0x0A010203u, 40001}.toString()), "10.1.2.3:40001");
}

TEST(AddressRange, ParsesAddressesAndBlocksAndNamesBadOnes) {
  const AddressRange one = parseAddressRange("10.1.2.3");
  EXPECT_TRUE(one.contains(address("10.1.2.3", 0).address));
  EXPECT_FALSE(one.contains(address("10.1.2.4", 0).address));
  const AddressRange block = parseAddressRange("172.16.0.0/12");
  EXPECT_TRUE(block.contains(address("172.31.255.255", 0).address));
  EXPECT_FALSE(block.contains(address("172.32.0.0", 0).address));
  EXPECT_TRUE(parseAddressRange("0.0.0.0/0").contains(address("8.8.8.8", 0).address));
  auto error = [](const std::string& text) {
    try {
      parseAddressRange(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_NE(error("10.1.2.300").find("\"10.1.2.300\" is not an IPv4 address"), std::string::npos);
  EXPECT_NE(error("10.0.0.0/33").find("0..32"), std::string::npos);
  EXPECT_NE(error("10.1.2.3/8").find("did you mean 10.0.0.0/8?"), std::string::npos) << error("10.1.2.3/8");
}

// The default admits the simulator LAN's private addresses and nothing from outside it.
TEST(HostSessions, SenderOutsideAllowedIsRefused) {
  HostSessions s;
  const auto t = Clock::now();
  EXPECT_EQ(s.admit(address("8.8.8.8", 5000), frame(1), t).admission, Admission::notAllowed);
  EXPECT_FALSE(s.active());
  EXPECT_EQ(s.admit(address("192.168.1.20", 5000), frame(1), t).admission, Admission::newSession);
  HostSessionSettings only;
  only.allowed = {parseAddressRange("127.0.0.1")};
  HostSessions strict(only);
  EXPECT_EQ(strict.admit(address("127.0.0.2", 5000), frame(1), t).admission, Admission::notAllowed);
  EXPECT_EQ(strict.admit(address("127.0.0.1", 5000), frame(1), t).admission, Admission::newSession);
}

TEST(HostSessions, ReorderedFramesWithinTheWindowAreStale) {
  HostSessions s;
  const auto from = address("10.0.0.5", 40000);
  auto t = Clock::now();
  EXPECT_EQ(s.admit(from, frame(11), t).reason, SessionReason::first);
  EXPECT_EQ(s.admit(from, frame(10), t += 1ms).admission, Admission::stale);       // arrives late
  EXPECT_EQ(s.admit(from, frame(11 - 30), t += 1ms).admission, Admission::stale);  // the window's edge
  EXPECT_EQ(s.admit(from, frame(12), t += 1ms).admission, Admission::apply);
  EXPECT_EQ(s.admit(from, frame(12), t += 1ms).admission, Admission::apply);  // a host that repeats its number
  // Frame numbers wrap at 2^32 in serial-number order.
  HostSessions w;
  EXPECT_EQ(w.admit(from, frame(0xffffffffu), t).admission, Admission::newSession);
  EXPECT_EQ(w.admit(from, frame(0), t += 1ms).admission, Admission::apply);
  EXPECT_EQ(w.admit(from, frame(0xffffffffu), t += 1ms).admission, Admission::stale);
}

// A restarted host's frame counter starts again: after an hour's session it is far behind, and
// it is followed at once, as is a frame number far ahead (and the real host after it).
TEST(HostSessions, FrameNumberFarBehindOrAheadIsARestart) {
  HostSessions s;
  const auto from = address("10.0.0.5", 40000);
  auto t = Clock::now();
  for (std::uint32_t n = 0; n <= 600; ++n) s.admit(from, frame(n), t += 33ms);
  const SessionDecision restart = s.admit(from, frame(0), t += 33ms);
  EXPECT_EQ(restart.admission, Admission::newSession);
  EXPECT_EQ(restart.reason, SessionReason::frameJump);
  EXPECT_EQ(s.admit(from, frame(1), t += 33ms).admission, Admission::apply);
  EXPECT_EQ(s.admit(from, frame(1 + 0x7fffffffu), t += 1ms).reason, SessionReason::frameJump);
  EXPECT_EQ(s.admit(from, frame(2), t += 32ms).reason, SessionReason::frameJump);  // the real host again
  EXPECT_EQ(s.admit(from, frame(3), t += 33ms).admission, Admission::apply);
  EXPECT_EQ(s.sessions(), 4u);
}

// Two host processes on one address (a test tool beside the real host, an old process still
// sending), both counting from frame 0 at 30 Hz, 1 ms apart, for 10 s: the node follows the first
// and only it, in one session, the other's 300 datagrams counted and dropped. When the first falls
// silent, the second takes over at its next datagram but one: within one host frame of the
// first's missing frame.
TEST(HostSessions, ASecondHostOnTheSameAddressDoesNotFlipThePicture) {
  HostSessions s;
  const Sender first = address("10.0.0.5", 40000), second = address("10.0.0.5", 40001);
  const auto t0 = Clock::now();
  int applied = 0, ignored = 0;
  for (std::uint32_t n = 0; n < 300; ++n) {
    const auto t = t0 + std::chrono::microseconds(33333 * n);
    const SessionDecision a = s.admit(first, frame(n), t);
    applied += a.admission == Admission::apply || a.admission == Admission::newSession;
    const SessionDecision b = s.admit(second, frame(n), t + 1ms);
    ignored += b.admission == Admission::otherPort;
  }
  EXPECT_EQ(applied, 300);
  EXPECT_EQ(ignored, 300);
  EXPECT_EQ(s.sessions(), 1u);
  EXPECT_EQ(s.host().port, 40000);
  // The first stops after frame 299 (its frame 300 would come at 10.000 s); the second goes on.
  const auto t300 = t0 + std::chrono::microseconds(33333 * 300);
  EXPECT_EQ(s.admit(second, frame(300), t300 + 1ms).admission, Admission::otherPort);  // 34 ms of silence
  const SessionDecision takeover = s.admit(second, frame(301), t300 + 1ms + 33333us);  // 67 ms: two intervals
  EXPECT_EQ(takeover.admission, Admission::newSession);
  EXPECT_EQ(takeover.reason, SessionReason::newPort);
  EXPECT_EQ(s.host().port, 40001);
  // And the first, should it come back, is now the second host beside a live one.
  EXPECT_EQ(s.admit(first, frame(302), t300 + 1ms + 66666us).admission, Admission::otherPort);
}

TEST(HostSessions, NewPortSilenceAndResetStartSessions) {
  HostSessions s;
  auto t = Clock::now();
  s.admit(address("10.0.0.5", 40000), frame(100), t);
  // A restarted process binds another source port; its first frame is followed at once.
  EXPECT_EQ(s.admit(address("10.0.0.5", 40001), frame(5), t += 33ms).reason, SessionReason::newPort);
  EXPECT_EQ(s.host().port, 40001);
  // Silent for longer than the gap: whatever comes next starts again.
  EXPECT_EQ(s.admit(address("10.0.0.5", 40001), frame(4), t += 1500ms).reason, SessionReason::gap);
  // IG Control's Reset/Standby: the host is (re)starting.
  cigi::IgControl reset = frame(5);
  reset.igMode = cigi::IgMode::resetStandby;
  EXPECT_EQ(s.admit(address("10.0.0.5", 40001), reset, t += 33ms).reason, SessionReason::resetMode);
  reset.hostFrameNumber = 6;
  EXPECT_EQ(s.admit(address("10.0.0.5", 40001), reset, t += 33ms).admission, Admission::apply);  // held in reset
  EXPECT_EQ(s.admit(address("10.0.0.5", 40001), frame(7), t += 33ms).admission, Admission::apply);
  reset.hostFrameNumber = 8;
  EXPECT_EQ(s.admit(address("10.0.0.5", 40001), reset, t += 33ms).reason, SessionReason::resetMode);  // reset again
  EXPECT_EQ(s.sessions(), 5u);
}

// A stray or spoofed datagram from another address never interrupts a live host, whatever its
// frame number; once the host has been silent for the gap another allowed address takes over.
TEST(HostSessions, AnotherAddressNeverInterruptsALiveHost) {
  HostSessions s;
  const auto host = address("10.0.0.5", 40000), other = address("10.0.0.66", 40000);
  auto t = Clock::now();
  s.admit(host, frame(600), t);
  EXPECT_EQ(s.admit(other, frame(600 + 0x7fffffffu), t += 1ms).admission, Admission::otherHost);
  for (std::uint32_t n = 601; n < 691; ++n) EXPECT_EQ(s.admit(host, frame(n), t += 33ms).admission, Admission::apply);
  EXPECT_EQ(s.admit(other, frame(1), t += 1100ms).reason, SessionReason::newAddress);
  EXPECT_EQ(s.host().address, other.address);
  EXPECT_EQ(s.sessions(), 2u);
}

namespace {
double secondsOf(const std::optional<skyig::ephemeris::UtcTime>& t) { return t ? t->secondsOfDay : -1.0; }

cigi::DecodedMessage timed(std::uint32_t n, std::uint32_t timestamp, bool withDate) {
  cigi::DecodedMessage m;
  m.packets = {frame(n, timestamp)};
  if (withDate) {
    cigi::CelestialSphereControl cs;
    cs.date = *cigi::composeDate({2026, 6, 21});
    cs.hour = 19;
    cs.minute = 30;
    m.packets.push_back(cs);
  }
  return m;
}
}  // namespace

// The host's clock moves by the timestamp's signed, bounded step: one tick back is not the
// 11.9 hours of a wrap (it is ignored: the host's time never runs backwards), the 32-bit wrap
// is one step on, a re-based clock and a new session's first timestamp continue the clock
// where it stands.
TEST(CigiState, TimestampStepsAreBoundedAndSessionsContinueTheClock) {
  CigiStateTracker t;
  const auto now = Clock::now();
  t.apply(timed(1, 0xffffffffu - ticks(0.5), true), now);
  const double before = secondsOf(t.clock().utcAt(now + 1s));
  t.apply(timed(2, 0xffffffffu - ticks(0.5) - 1, false), now);  // one tick backwards
  EXPECT_NEAR(secondsOf(t.clock().utcAt(now + 1s)), before, 1e-9);
  t.apply(timed(3, ticks(0.5), false), now + 1s);  // 1 s and a tick on, across the wrap
  EXPECT_NEAR(secondsOf(t.clock().utcAt(now + 1s)), before + 1e-5, 1e-6);
  EXPECT_EQ(t.timestampJumps(), 0u);
  t.apply(timed(4, ticks(20000.0), false), now + 1100ms);  // re-based: 5.5 h on
  EXPECT_NEAR(secondsOf(t.clock().utcAt(now + 1100ms)), before + 1e-5 + 0.1, 1e-6);
  EXPECT_EQ(t.timestampJumps(), 1u);
  // A restarted host stamps from zero: the clock goes on from where it stood.
  t.startSession();
  t.apply(timed(0, 5, false), now + 1200ms);
  EXPECT_NEAR(secondsOf(t.clock().utcAt(now + 1200ms)), before + 1e-5 + 0.2, 1e-6);
  EXPECT_EQ(t.timestampJumps(), 1u);
  // A 90x time-lapse stamping its sim clock: after a second the rate is known.
  for (int k = 1; k <= 30; ++k) t.apply(timed(k, 5 + ticks(90.0 * k / 20.0), false), now + 1200ms + k * 50ms);
  ASSERT_TRUE(t.messageHostTime());
  EXPECT_NEAR(t.messageHostTime()->rate, 90.0, 1e-6);
}

// A valid IG Control at the front of a malformed datagram moves nothing: the datagram is
// rejected whole, counted, and the last good state is kept.
TEST(CigiReceiver, MalformedDatagramIsRejectedWhole) {
  NodeStats stats;
  Latest<HostSnapshot> out;
  CigiReceiver r(stats, out);
  const auto from = address("127.0.0.1", 40000);
  std::vector<std::uint8_t> bytes;
  cigi::CelestialSphereControl cs;
  cs.date = *cigi::composeDate({2026, 6, 21});
  cs.hour = 19;
  cs.minute = 30;
  const cigi::Packet good[] = {frame(1, 1'000'000), cs};
  ASSERT_EQ(cigi::encodeMessage(good, skyig::protocol::ByteOrder::big, bytes), "");
  const auto t = Clock::now();
  r.handle(bytes, from, t);
  ASSERT_EQ(out.version(), 1u);
  const double shown = secondsOf(out.get()->utcAt(t + 1s));
  // The next frame: its IG Control (a timestamp one tick back), then a truncated packet.
  const cigi::Packet front[] = {frame(2, 999'999), cs};
  ASSERT_EQ(cigi::encodeMessage(front, skyig::protocol::ByteOrder::big, bytes), "");
  bytes.resize(bytes.size() - 3);
  r.handle(bytes, from, t + 33ms);
  EXPECT_EQ(stats.malformedDatagrams.load(), 1u);
  EXPECT_EQ(out.version(), 1u);
  EXPECT_EQ(out.get()->state.hostFrame, 1u);
  EXPECT_NEAR(secondsOf(out.get()->utcAt(t + 1s)), shown, 1e-9);
}

// A re-based host clock reaches the counters and leaves the sim clock where it stood.
TEST(CigiReceiver, TimestampJumpIsCountedAndMovesNothing) {
  NodeStats stats;
  Latest<HostSnapshot> out;
  CigiReceiver r(stats, out);
  const auto from = address("127.0.0.1", 40000);
  cigi::CelestialSphereControl cs;
  cs.date = *cigi::composeDate({2026, 6, 21});
  cs.hour = 19;
  cs.minute = 30;
  std::vector<std::uint8_t> bytes;
  const cigi::Packet first[] = {frame(1, 1'000'000), cs};
  ASSERT_EQ(cigi::encodeMessage(first, skyig::protocol::ByteOrder::big, bytes), "");
  const auto t = Clock::now();
  r.handle(bytes, from, t);
  const double shown = secondsOf(out.get()->utcAt(t + 1s));
  const cigi::Packet jumped[] = {frame(2, 1'000'000 + ticks(20000.0))};
  ASSERT_EQ(cigi::encodeMessage(jumped, skyig::protocol::ByteOrder::big, bytes), "");
  r.handle(bytes, from, t + 33ms);
  EXPECT_EQ(out.version(), 2u);
  EXPECT_EQ(stats.timestampJumps.load(), 1u);
  EXPECT_NEAR(secondsOf(out.get()->utcAt(t + 1s)), shown, 1e-6);
}

// With Rate Control, a 30 Hz host sampled by a 60 Hz IG moves smoothly: half a host frame
// after a sample the ownship has moved half a frame's worth.
TEST(OwnshipPredictor, DeadReckonsWithHostRates) {
  OwnshipPredictor p;
  const auto t0 = Clock::now();
  OwnshipRates r;
  r.valid = true;
  r.x = 50.0;       // 50 m/s north
  r.yawRate = 6.0;  // deg/s
  p.addSample({45.0, 7.0, 1000.0, {350.0, 0.0, 0.0}}, t0, r);
  const skyig::sky::Ownship o = p.at(t0 + std::chrono::microseconds(16667));
  EXPECT_NEAR((o.latitudeDeg - 45.0) * 111132.0, 50.0 * 0.016667, 0.01);  // metres of latitude at 45 deg
  EXPECT_NEAR(o.attitude.yawDeg, 350.1, 1e-3);
  // Across north the heading wraps.
  EXPECT_NEAR(p.at(t0 + 200ms).attitude.yawDeg, 351.2, 1e-3);
  // A silent host: prediction stops after 0.25 s.
  EXPECT_NEAR(p.at(t0 + 10s).latitudeDeg, p.at(t0 + 250ms).latitudeDeg, 1e-12);
}

TEST(OwnshipPredictor, ExtrapolatesFromTwoSamplesWithoutRates) {
  OwnshipPredictor p;
  const auto t0 = Clock::now();
  p.addSample({45.0, 7.0, 1000.0, {359.0, 0.0, 10.0}}, t0, {});
  p.addSample({45.0, 7.0, 1003.0, {1.0, 0.0, 12.0}}, t0 + 100ms, {});
  const skyig::sky::Ownship o = p.at(t0 + 150ms);
  EXPECT_NEAR(o.heightM, 1004.5, 1e-9);
  EXPECT_NEAR(o.attitude.yawDeg, 2.0, 1e-9);  // 359 -> 1 is +2 deg, not -358
  EXPECT_NEAR(o.attitude.rollDeg, 13.0, 1e-9);
  // An older sample is ignored.
  p.addSample({0.0, 0.0, 0.0, {0.0, 0.0, 0.0}}, t0 + 50ms, {});
  EXPECT_NEAR(p.at(t0 + 100ms).heightM, 1003.0, 1e-9);
}

// Two datagrams that arrive back to back (one held up and sent with the next) are no
// velocity: without timestamps the estimate reaches back to a sample far enough apart, with
// them the host's clock times the step (here a 90x time-lapse's sim clock, at its rate). A
// 15 deg/s turn is predicted as 15 deg/s either way.
TEST(OwnshipPredictor, BackToBackSamplesDoNotSpinTheView) {
  for (const bool timestamps : {false, true}) {
    OwnshipPredictor p;
    const auto t0 = Clock::now();
    auto sample = [&](int k, Clock::time_point arrival) {
      p.addSample({45.0, 7.0, 1000.0, {std::fmod(350.0 + 0.5 * k, 360.0), 0.0, 0.0}}, arrival, {},
                  timestamps ? std::optional<HostTime>({90.0 * k / 30.0, 90.0}) : std::nullopt);
    };
    sample(0, t0);
    sample(1, t0 + 33333us);
    sample(2, t0 + 66667us + 33333us);  // held up ...
    sample(3, t0 + 100000us + 10us);    // ... and sent with the next
    const double predicted = p.at(t0 + 100000us + 10us + 50ms).attitude.yawDeg;
    EXPECT_NEAR(wrap180(predicted - (350.0 + 0.5 * 3 + 15.0 * 0.05)), 0.0, 0.05) << "timestamps " << timestamps;
  }
}

// A latitude step of a degree in one frame is 3.3 km/s: noise, bounded to what an aircraft can
// do; near a pole the prediction crosses it onto the far meridian, never past 90 degrees.
TEST(OwnshipPredictor, BoundedAndAlwaysAValidPose) {
  OwnshipPredictor p;
  const auto t0 = Clock::now();
  p.addSample({10.0, 179.9, 1000.0, {0.0, 89.0, 179.0}}, t0, {});
  p.addSample({11.0, -179.9, 1000.0, {0.0, 89.5, 179.5}}, t0 + 33ms, {});
  const skyig::sky::Ownship o = p.at(t0 + 33ms + 250ms);
  EXPECT_LT((o.latitudeDeg - 11.0) * 111000.0, kMaxGroundSpeedMps * 0.25 + 1.0);
  EXPECT_GT(o.longitudeDeg, -180.0);
  EXPECT_LE(o.longitudeDeg, 180.0);
  EXPECT_LE(o.attitude.pitchDeg, 90.0);  // over the top: pitch back below 90, facing back
  EXPECT_GE(o.attitude.yawDeg, 0.0);
  EXPECT_LT(o.attitude.yawDeg, 360.0);
  EXPECT_GT(o.attitude.rollDeg, -180.0);
  EXPECT_LE(o.attitude.rollDeg, 180.0);
  OwnshipRates north;
  north.valid = true;
  north.x = 5000.0;  // beyond the bound: flown at 1000 m/s
  OwnshipPredictor pole;
  pole.addSample({89.9995, 20.0, 1000.0, {0.0, 0.0, 0.0}}, t0, north);
  const skyig::sky::Ownship q = pole.at(t0 + 250ms);
  EXPECT_LE(q.latitudeDeg, 90.0);
  EXPECT_NEAR(q.longitudeDeg, -160.0, 1e-6);                           // over the pole
  EXPECT_NEAR(q.attitude.yawDeg, 180.0, 1e-6);                         // now heading south
  EXPECT_NEAR(90.0 - q.latitudeDeg, 250.0 / 111694.0 - 0.0005, 2e-6);  // 250 m, 55 m past the pole
}
