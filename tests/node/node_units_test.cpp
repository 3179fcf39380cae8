// The node's pure parts: the sim clock, applying CIGI to the host state,
// scripted paths.
#include "protocol/cigi/date.h"
#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "node/host/cigi_state.h"
#include "node/host/host_path.h"
#include "node/host/host_weather.h"
#include "node/config/node_config.h"
#include "node/host/ownship_predictor.h"
#include "node/host/sim_clock.h"
#include "node/frame/state_dump.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include <cmath>

using namespace skyig::services;
namespace cigi = skyig::protocol::cigi;
using namespace std::chrono_literals;

namespace {
double secondsOf(const std::optional<skyig::ephemeris::UtcTime>& t) { return t ? t->secondsOfDay : -1.0; }

// An IG Control of host frame `frame` stamped `ticks` (10 us each).
cigi::IgControl igControl(std::uint32_t frame, std::uint32_t ticks) {
  cigi::IgControl ig;
  ig.hostFrameNumber = frame;
  ig.timestamp = ticks;
  ig.timestampValid = true;
  return ig;
}

// A Celestial Sphere Control of midsummer's day 2026 at hour:minute.
cigi::CelestialSphereControl midsummerAt(int hour, int minute) {
  cigi::CelestialSphereControl cs;
  cs.date = *cigi::composeDate({2026, 6, 21});
  cs.hour = static_cast<std::uint8_t>(hour);
  cs.minute = static_cast<std::uint8_t>(minute);
  return cs;
}
}  // namespace

// Hour and minute only: the clock starts at the stated minute, runs smoothly, never leaves
// the stated minute, and a rollover pins it to the host's clock.
TEST(SimClock, MinuteOnlyTimeRunsSmoothlyAndLocksAtTheRollover) {
  SimClock c;
  // The host's true time is 19:00:42.0 at continuous time 100 s; it says 19:00.
  const double trueOffset = 19 * 3600.0 + 42.0 - 100.0;
  for (double t = 100.0; t < 200.0; t += 1.0 / 30.0) {
    const double truth = t + trueOffset;
    c.observe({2026, 6, 21, std::floor(truth / 60.0) * 60.0}, t);
    const double shown = secondsOf(c.at(t));
    // Always inside the minute the host stated (the sun never runs ahead or behind).
    EXPECT_GE(shown, std::floor(truth / 60.0) * 60.0 - 1e-6);
    EXPECT_LT(shown, std::floor(truth / 60.0) * 60.0 + 60.0);
  }
  // After the 19:01 rollover (at t = 118 s) the clock agrees with the host to one host frame.
  EXPECT_NEAR(secondsOf(c.at(150.0)), 150.0 + trueOffset, 1.0 / 30.0 + 1e-6);
  // Between observations it keeps running: 0.5 s later it shows 0.5 s more.
  EXPECT_NEAR(secondsOf(c.at(150.5)) - secondsOf(c.at(150.0)), 0.5, 1e-6);
}

TEST(SimClock, NewScenarioTimeRestartsTheClock) {
  SimClock c;
  c.observe({2026, 6, 21, 19 * 3600.0}, 10.0);
  c.observe({2026, 12, 24, 6 * 3600.0 + 30 * 60.0}, 11.0);
  const auto t = c.at(11.5);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->month, 12);
  EXPECT_EQ(t->day, 24);
  EXPECT_NEAR(t->secondsOfDay, 6 * 3600.0 + 30 * 60.0 + 0.5, 1e-3);
}

TEST(SimClock, CrossesMidnight) {
  SimClock c;
  c.observe({2026, 12, 31, 23 * 3600.0 + 59 * 60.0}, 0.0);
  c.observe({2026, 12, 31, 23 * 3600.0 + 59 * 60.0}, 30.0);
  const auto t = c.at(90.0);
  ASSERT_TRUE(t);
  EXPECT_EQ(t->year, 2027);
  EXPECT_EQ(t->month, 1);
  EXPECT_EQ(t->day, 1);
  EXPECT_NEAR(t->secondsOfDay, 30.0, 1e-3);
}

namespace {
cigi::DecodedMessage messageOf(std::uint32_t frame, const cigi::EntityControl& e) {
  cigi::DecodedMessage m;
  cigi::IgControl ig;
  ig.hostFrameNumber = frame;
  m.packets = {ig, e};
  return m;
}
}  // namespace

TEST(CigiState, OwnshipIsEntityZeroAndBadValuesKeepTheLastGood) {
  CigiStateTracker t;
  cigi::EntityControl e;
  e.latitudeDeg = 47.0;
  e.longitudeDeg = 11.0;
  e.yawDeg = 90.0f;
  t.apply(messageOf(1, e), Clock::now());
  EXPECT_EQ(t.state().ownship.latitudeDeg, 47.0);
  cigi::EntityControl other = e;
  other.entityId = 3;
  other.latitudeDeg = 10.0;
  t.apply(messageOf(2, other), Clock::now());
  EXPECT_EQ(t.state().ownship.latitudeDeg, 47.0);  // another entity is not the ownship
  cigi::EntityControl bad = e;
  bad.latitudeDeg = std::nan("");
  EXPECT_EQ(t.apply(messageOf(3, bad), Clock::now()), 1);
  bad.latitudeDeg = 91.0;
  EXPECT_EQ(t.apply(messageOf(4, bad), Clock::now()), 1);
  EXPECT_EQ(t.state().ownship.latitudeDeg, 47.0);
  EXPECT_EQ(t.state().ownship.attitude.yawDeg, 90.0);
}

// Two nodes fed one stream count the host's time to the same bit, whatever their own clocks
// read (machines booted hours apart: arrival instants of different binary magnitude) and
// however the network delays each datagram: the host's time of a message is its timestamp's
// ticks since the stream's first, never a running sum on top of a local instant.
TEST(CigiState, TwoNodesCountTheHostsTimeToTheBit) {
  CigiStateTracker a, b;
  const Clock::time_point bootA{std::chrono::seconds(37)}, bootB{std::chrono::seconds(400000)};
  for (std::uint32_t k = 0; k < 300; ++k) {
    cigi::DecodedMessage m;
    m.packets = {igControl(k, k * 3333 + (k % 3 == 0 ? 1 : 0)),  // 30 Hz, a jittering host clock
                 midsummerAt(19, static_cast<int>(30 + k / 1800))};
    const auto delay = std::chrono::microseconds(k * 33333 + (k * 7919) % 2000);  // network jitter
    a.apply(m, bootA + delay);
    b.apply(m, bootB + delay + std::chrono::microseconds(k % 5 * 100));
    ASSERT_TRUE(a.messageHostTime().has_value() == b.messageHostTime().has_value()) << k;
    if (a.messageHostTime()) {
      EXPECT_EQ(a.messageHostTime()->seconds, b.messageHostTime()->seconds) << k;
    }
    EXPECT_EQ(a.clock().continuousAt(a.state().received), b.clock().continuousAt(b.state().received)) << k;
    EXPECT_EQ(a.state().utc.secondsOfDay, b.state().utc.secondsOfDay) << k;
  }
}

TEST(CigiState, CelestialDateAndViewsApply) {
  CigiStateTracker t;
  cigi::DecodedMessage m;
  const cigi::IgControl ig = igControl(5, 100000);  // 1 s
  cigi::CelestialSphereControl cs = midsummerAt(19, 30);
  cigi::ViewDefinition vd;
  vd.viewId = 1;
  vd.leftEnable = vd.rightEnable = true;
  vd.leftDeg = -20.0f;
  vd.rightDeg = 35.0f;
  cigi::ViewControl vc;
  vc.viewId = 1;
  vc.yawEnable = true;
  vc.yawDeg = -60.0f;
  m.packets = {ig, cs, vd, vc};
  const auto now = Clock::now();
  EXPECT_EQ(t.apply(m, now), 0);
  ASSERT_TRUE(t.state().timeValid);
  EXPECT_EQ(t.state().utc.day, 21);
  EXPECT_NEAR(t.state().utc.secondsOfDay, 19 * 3600.0 + 30 * 60.0, 1e-3);
  EXPECT_NEAR(secondsOf(t.clock().utcAt(now + 2s)), 19 * 3600.0 + 30 * 60.0 + 2.0, 1e-3);
  ASSERT_EQ(t.state().views.size(), 1u);
  ASSERT_NE(t.state().views.find(1), nullptr);
  EXPECT_EQ(*t.state().views.find(1)->leftDeg, 20.0);
  EXPECT_EQ(*t.state().views.find(1)->rightDeg, 35.0);
  EXPECT_EQ(*t.state().views.find(1)->yawDeg, -60.0);
  EXPECT_FALSE(t.state().views.find(1)->upDeg.has_value());
  cs.date = 2302026;  // 30 February
  m.packets = {ig, cs};
  EXPECT_EQ(t.apply(m, now), 1);
}

// A View Definition that moves one edge of a pair past the other (left only at CIGI +80 where the
// channel's right edge is at 30; top only at -80 where its bottom is at -20) would invert the
// frustum: refused (counted) with the view left as it was; the same edge within the frustum
// applies. The check uses the host's last edge where it set one, else the channel's.
TEST(CigiState, OneEdgeMovedPastTheOtherIsRefused) {
  CigiStateTracker t;
  t.setChannelFrusta({skyig::sky::Frustum{30.0, 30.0, 20.0, 20.0}, skyig::sky::Frustum{45.0, 45.0, 30.0, 30.0}});
  auto definition = [](std::uint16_t viewId, std::optional<float> left, std::optional<float> right,
                       std::optional<float> top, std::optional<float> bottom) {
    cigi::ViewDefinition vd;
    vd.viewId = viewId;
    vd.leftEnable = left.has_value();
    vd.rightEnable = right.has_value();
    vd.topEnable = top.has_value();
    vd.bottomEnable = bottom.has_value();
    vd.leftDeg = left.value_or(0.0f);
    vd.rightDeg = right.value_or(0.0f);
    vd.topDeg = top.value_or(0.0f);
    vd.bottomDeg = bottom.value_or(0.0f);
    cigi::DecodedMessage m;
    m.packets = {cigi::IgControl{}, vd};
    return m;
  };
  const auto now = Clock::now();
  EXPECT_EQ(t.apply(definition(0, 80.0f, {}, {}, {}), now), 1);  // left at +80 against right at 30
  EXPECT_EQ(t.apply(definition(0, {}, {}, -80.0f, {}), now), 1);  // top at -80 against bottom at -20
  EXPECT_EQ(t.apply(definition(1, {}, -50.0f, {}, {}), now), 1);  // right at -50 against left at -45
  EXPECT_EQ(t.state().views.find(0), nullptr);
  EXPECT_EQ(t.state().views.find(1), nullptr);
  // Within the frustum: applied; then judged against the host's own edge.
  EXPECT_EQ(t.apply(definition(0, 25.0f, {}, {}, {}), now), 0);  // left edge at 25 deg right of the boresight
  ASSERT_NE(t.state().views.find(0), nullptr);
  EXPECT_EQ(*t.state().views.find(0)->leftDeg, -25.0);
  EXPECT_EQ(t.apply(definition(0, {}, -26.0f, {}, {}), now), 1);  // right edge left of that left edge
  EXPECT_EQ(t.apply(definition(0, {}, 31.0f, {}, {}), now), 0);  // 6 deg wide: applied
  EXPECT_EQ(*t.state().views.find(0)->rightDeg, 31.0);
  // A view without a channel: a pair that crosses is refused, a single edge cannot be judged.
  EXPECT_EQ(t.apply(definition(7, 10.0f, -20.0f, {}, {}), now), 1);
  EXPECT_EQ(t.apply(definition(7, 10.0f, {}, {}, {}), now), 0);
}

// A message is one host frame: an Entity Control with a NaN latitude (or a roll of 400 deg)
// refuses the whole message, so neither the pose, the frame number Start of Frame acknowledges,
// nor the host's clock moves; the next good message continues from the last good one.
TEST(CigiState, AMessageWithABadValueIsRefusedWhole) {
  CigiStateTracker t;
  auto message = [](std::uint32_t frame, std::uint32_t ticks, double latitude, double rollDeg) {
    cigi::EntityControl e;
    e.latitudeDeg = latitude;
    e.longitudeDeg = 11.0;
    e.altitudeM = 600.0;
    e.rollDeg = static_cast<float>(rollDeg);
    cigi::DecodedMessage m;
    m.packets = {igControl(frame, ticks), e, midsummerAt(19, 30)};
    return m;
  };
  const auto t0 = Clock::now();
  ASSERT_EQ(t.apply(message(5, 100000, 47.0, 0.0), t0), 0);
  const HostState good = t.state();
  const double clockAtGood = t.clock().continuousAt(t0 + 1s);
  const double baseAtGood = t.clock().timestampBaseS;
  for (const auto& [latitude, roll] : {std::pair{std::nan(""), 0.0}, std::pair{47.5, 400.0}}) {
    EXPECT_EQ(t.apply(message(6, 103300, latitude, roll), t0 + 33ms), 1);
    EXPECT_EQ(t.state().hostFrame, 5u);
    EXPECT_EQ(t.state().ownship.latitudeDeg, 47.0);
    EXPECT_EQ(t.state().updates, good.updates);
    EXPECT_EQ(t.state().received, good.received);
    EXPECT_EQ(t.clock().continuousAt(t0 + 1s), clockAtGood);
  }
  // The next good frame: its timestamp steps from frame 5's (no jump counted), its pose applies.
  ASSERT_EQ(t.apply(message(7, 106600, 47.1, 10.0), t0 + 66ms), 0);
  EXPECT_EQ(t.state().hostFrame, 7u);
  EXPECT_EQ(t.state().ownship.latitudeDeg, 47.1);
  EXPECT_EQ(t.timestampJumps(), 0u);
  EXPECT_NEAR(t.clock().timestampBaseS - baseAtGood, 0.066, 1e-9);
}

TEST(HostPath, InterpolatesHeadingTheShortWayAndNamesBadLines) {
  const HostPath p = HostPath::parse("time,lat,lon,alt,yaw,pitch,roll\n0,47,11,600,350,0,0\n10,47.1,11,700,10,0,0\n", "p.csv");
  EXPECT_NEAR(p.at(5.0).attitude.yawDeg, 0.0, 1e-9);
  EXPECT_NEAR(p.at(5.0).heightM, 650.0, 1e-9);
  EXPECT_NEAR(p.ratesAt(5.0).yawRate, 2.0, 1e-6);
  EXPECT_NEAR(p.ratesAt(5.0).x, 0.1 * 3.14159265 / 180.0 * 6371008.8 / 10.0, 0.01);
  try {
    HostPath::parse("0,47,11,600,350,0,0\n5,47,11,600\n", "p.csv");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), "p.csv:2: expected 7 numbers: time_s, latitude, longitude, altitude_m, yaw, pitch, roll");
  }
  EXPECT_THROW(HostPath::parse("0,47,11,600,350,0,0\n0,47,11,600,350,0,0\n", "p.csv"), ConfigError);
}

// The host emulator's weather script holds each line until the next (before the first: the
// first), and names the file and line of a bad one; the bundled example parses.
TEST(HostWeather, HoldsEachStepAndNamesBadLines) {
  const HostWeather w = HostWeather::parse("time,vis,rh,fog,top\n0,3000,95,200,150\n10,8000,80,0,0\n", "w.csv");
  EXPECT_EQ(w.at(-1.0).fogVisibilityM, 200.0);
  EXPECT_EQ(w.at(9.99).visibilityM, 3000.0);
  EXPECT_EQ(w.at(10.0).visibilityM, 8000.0);
  EXPECT_EQ(w.at(1e6).fogVisibilityM, 0.0);
  try {
    HostWeather::parse("0,3000,95,200,150\n5,3000,95,200,0\n", "w.csv");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("w.csv:2: a fog needs", 0), 0u) << e.what();
  }
  EXPECT_THROW(HostWeather::parse("0,3000,150,0,0\n", "w.csv"), ConfigError);  // 150 % humidity
  EXPECT_THROW(HostWeather::parse("0,nan,50,0,0\n", "w.csv"), ConfigError);
  EXPECT_THROW(HostWeather::parse("# nothing\n", "w.csv"), ConfigError);
  const HostWeather bundled = HostWeather::load(std::string(SKYIG_SOURCE_DIR) + "/config/fog_lifting.csv");
  EXPECT_EQ(bundled.at(0.0).fogVisibilityM, 200.0);
  EXPECT_EQ(bundled.at(60.0).visibilityM, 40000.0);
  EXPECT_FALSE(bundled.at(60.0).precipitation);
  // Precipitation after the fog: a kind (or none), its severity, visibility (0: the severity's)
  // and top; the first data line may name it (it starts with its time: not a header).
  const HostWeather rain = HostWeather::parse("0,3000,95,0,0,rain,3,0,1200\n5,9000,80,0,0,none,0,0,1500\n", "r.csv");
  EXPECT_EQ(rain.at(0.0).precipitation, skyig::weather::Precipitation::rain);
  EXPECT_EQ(rain.at(0.0).precipitationSeverity, 3);
  EXPECT_EQ(rain.at(0.0).precipitationTopM, 1200.0);
  EXPECT_FALSE(rain.at(5.0).precipitation);
  try {
    HostWeather::parse("0,3000,95,0,0,drizzle,3,0,1200\n", "r.csv");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("r.csv:1: precipitation \"drizzle\"", 0), 0u) << e.what();
  }
  EXPECT_THROW(HostWeather::parse("0,3000,95,0,0,rain,6,0,1200\n", "r.csv"), ConfigError);  // severity 6
  EXPECT_THROW(HostWeather::parse("0,3000,95,0,0,rain,3\n", "r.csv"), ConfigError);         // fields missing
  EXPECT_THROW(HostWeather::parse("0,3000,95,0,0,rain,3,0,1200,7\n", "r.csv"), ConfigError);
  const HostWeather showers = HostWeather::load(std::string(SKYIG_SOURCE_DIR) + "/config/showers.csv");
  EXPECT_EQ(showers.at(59.0).timeS, 59.0);  // a change every second for a minute
  EXPECT_FALSE(showers.at(0.0).cloud) << "no cloud column: layer 1 is left to --cloud";
  // Cloud layer 1 after the precipitation: a spec, or none (sent switched off).
  const HostWeather decks =
      HostWeather::parse("0,9000,80,0,0,none,0,0,1500,stratus:900:400:100\n30,9000,80,0,0,none,0,0,1500,none\n", "c.csv");
  ASSERT_TRUE(decks.at(0.0).cloud);
  EXPECT_TRUE(decks.at(0.0).cloud->enabled);
  EXPECT_EQ(decks.at(0.0).cloud->baseM, 900.0);
  ASSERT_TRUE(decks.at(30.0).cloud);
  EXPECT_FALSE(decks.at(30.0).cloud->enabled);
  try {
    HostWeather::parse("0,9000,80,0,0,none,0,0,1500,stratus:900:400:100\n5,9000,80,0,0,none,0,0,1500,stratus:900:-4\n",
                       "c.csv");
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("c.csv:2: cloud: ", 0), 0u) << e.what();
  }
  const HostWeather ceiling = HostWeather::load(std::string(SKYIG_SOURCE_DIR) + "/config/ceiling_lowering.csv");
  ASSERT_TRUE(ceiling.at(0.0).cloud);
  ASSERT_TRUE(ceiling.at(60.0).cloud);
  EXPECT_GT(ceiling.at(0.0).cloud->baseM, ceiling.at(60.0).cloud->baseM) << "the ceiling comes down";
}

// A CIGI 4.0 host states the seconds (a float the 3.3 Celestial Sphere Control lacks): the
// clock starts at the stated instant, not at the start of the minute, runs on the host's IG
// Control timestamps (at their 4.0 offset), and the node will answer in 4.0. The same
// statement in 3.3 gives the minute only.
TEST(CigiState, Cigi4SecondsAndTimestampSetTheClockAndTheReplyVersion) {
  cigi::IgControl ig = igControl(7, 100000);  // 1 s
  cigi::CelestialSphereControl cs = midsummerAt(19, 30);
  cs.seconds = 42.25f;
  auto through = [](bool v4, const std::vector<cigi::Packet>& packets) {  // the bytes as sent, decoded
    std::vector<std::uint8_t> bytes;
    EXPECT_EQ(v4 ? cigi::encodeMessage4(packets, skyig::protocol::ByteOrder::little, bytes)
                 : cigi::encodeMessage(packets, skyig::protocol::ByteOrder::little, bytes),
              "");
    return cigi::decodeMessage(bytes);
  };
  const auto now = Clock::now();
  CigiStateTracker t4;
  EXPECT_EQ(t4.apply(through(true, {ig, cs}), now), 0);
  EXPECT_EQ(t4.state().cigiMajorVersion, 4);
  EXPECT_NEAR(t4.state().utc.secondsOfDay, 19 * 3600.0 + 30 * 60.0 + 42.25, 1e-3);
  // Half a second later by the host's timestamp, the host states 42.75 s: the clock agrees.
  ig.hostFrameNumber = 8;
  ig.timestamp = 150000;
  cs.seconds = 42.75f;
  EXPECT_EQ(t4.apply(through(true, {ig, cs}), now + 500ms), 0);
  EXPECT_NEAR(secondsOf(t4.clock().utcAt(now + 500ms)), 19 * 3600.0 + 30 * 60.0 + 42.75, 1e-3);
  EXPECT_NEAR(secondsOf(t4.clock().utcAt(now + 1500ms)), 19 * 3600.0 + 30 * 60.0 + 43.75, 1e-3);
  // Seconds outside [0, 60) are rejected and the clock kept.
  ig.hostFrameNumber = 9;
  cs.seconds = 60.0f;
  EXPECT_EQ(t4.apply(through(true, {ig, cs}), now + 500ms), 1);

  CigiStateTracker t3;
  ig.hostFrameNumber = 7;
  cs.seconds = 42.25f;  // not on the wire in 3.3
  EXPECT_EQ(t3.apply(through(false, {ig, cs}), now), 0);
  EXPECT_EQ(t3.state().cigiMajorVersion, 3);
  EXPECT_NEAR(t3.state().utc.secondsOfDay, 19 * 3600.0 + 30 * 60.0, 1e-3);
}

// The state dump records each view's goggle as the frame used it: a channel the host switched to
// its class B goggle with a manual gain of 0.375 says so, an eye channel says its goggle is off.
TEST(StateDump, EachViewRecordsItsGoggle) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("skyig-state-dump-" + std::to_string(::getpid()) + ".jsonl");
  skyig::sky::ChannelConfig eye, goggle;
  eye.name = "front";
  goggle.name = "chin";
  goggle.band = skyig::sky::SpectralBand::NvisClassB;
  goggle.goggle.phosphor = skyig::sky::Phosphor::P45;
  goggle.goggle.automaticGain = false;
  goggle.goggle.gain = 0.375;
  const skyig::sky::SkyState state = skyig::sky::buildSkyState(skyig::sky::ObserverState{}, skyig::sky::SkyConditions{});
  {
    StateDump dump(path.string());
    dump.write(7, nullptr, state, FramePose{{}, {eye, goggle}});
  }
  std::ifstream in(path);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  std::filesystem::remove(path);
  const auto j = nlohmann::json::parse(line);
  const auto& views = j["used"]["views"];
  ASSERT_EQ(views.size(), 2u);
  EXPECT_EQ(views[0]["goggle"]["on"], false);
  EXPECT_EQ(views[0]["goggle"]["class"], "A");  // the configured class, were it switched on
  EXPECT_EQ(views[1]["goggle"]["on"], true);
  EXPECT_EQ(views[1]["goggle"]["class"], "B");
  EXPECT_EQ(views[1]["goggle"]["phosphor"], "P45");
  EXPECT_EQ(views[1]["goggle"]["automatic_gain"], false);
  EXPECT_EQ(views[1]["goggle"]["gain"], 0.375);
}
