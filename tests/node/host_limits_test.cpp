// Bounded per-datagram work: View Control floods on loopback, view ids beyond the maximum.
#include "protocol/cigi/encoder.h"
#include "node/transport/cigi_receiver.h"
#include "node/host/cigi_state.h"
#include "node/common/latest.h"
#include "node/host/node_stats.h"
#include "node/transport/udp_socket.h"
#include "node/common/warning_throttle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <thread>
#include <utility>
#include <vector>

namespace skyig::services {
namespace {

namespace cigi = protocol::cigi;
using namespace std::chrono_literals;

cigi::ViewControl viewControl(std::uint16_t id, float yaw) {
  cigi::ViewControl v;
  v.viewId = id;
  v.yawEnable = true;
  v.yawDeg = yaw;
  return v;
}

TEST(ViewTable, ViewIdsAtOrAboveTheMaximumAreCountedAndDropped) {
  CigiStateTracker t;
  t.setMaxViews(4);
  cigi::DecodedMessage m;
  cigi::IgControl ig;
  m.packets = {ig, viewControl(3, 10.0f), viewControl(4, 20.0f), viewControl(65535, 30.0f), viewControl(0, 40.0f)};
  EXPECT_EQ(t.apply(m, Clock::now()), 0);
  EXPECT_EQ(t.droppedViews(), 2u);
  EXPECT_EQ(t.state().views.size(), 2u);
  ASSERT_NE(t.state().views.find(3), nullptr);
  EXPECT_EQ(*t.state().views.find(3)->yawDeg, 10.0);
  EXPECT_EQ(*t.state().views.find(0)->yawDeg, 40.0);
  EXPECT_EQ(t.state().views.find(4), nullptr);
  // Sensor Control (a view's goggle) is bounded alike.
  cigi::SensorControl goggle;
  goggle.sensorOn = true;
  goggle.viewId = 4;
  m.packets = {ig, goggle};
  t.apply(m, Clock::now());
  EXPECT_EQ(t.droppedViews(), 3u);
  EXPECT_EQ(t.state().views.find(4), nullptr);
  // The configured maximum never exceeds the table.
  t.setMaxViews(1000);
  m.packets = {ig, viewControl(kViewTableCapacity, 1.0f)};
  t.apply(m, Clock::now());
  EXPECT_EQ(t.droppedViews(), 4u);
}

// A host at 60 Hz and, on the same port, two 65 KB datagrams a second each holding ~2000 View
// Controls for distinct ids: the host's own datagrams still reach the render thread's snapshot
// within a millisecond (receive to publish, HostSnapshot::published - HostState::received).
TEST(ViewTable, ViewControlFloodsKeepTheHostsDatagramsUnderAMillisecond) {
  NodeStats stats;
  Latest<HostSnapshot> latest;
  CigiReceiver receiver(stats, latest);
  UdpSocket socket({"127.0.0.1", 0});
  const sockaddr_in to = toSockaddr(socket.localEndpoint());
  std::atomic<bool> stop{false};
  std::thread rx([&] { receiver.run(socket, stop); });

  // What the render thread would see: every snapshot's latency, by kind.
  std::vector<double> hostUs, floodUs;
  std::atomic<bool> stopWatch{false};
  std::thread watch([&] {
    std::uint64_t seen = 0;
    while (!stopWatch) {
      if (latest.version() == seen) {
        std::this_thread::sleep_for(20us);
        continue;
      }
      seen = latest.version();
      const auto s = latest.get();
      const double us = std::chrono::duration<double, std::micro>(s->published - s->state.received).count();
      // The host's datagrams carry the ownship; the flood's carry views only.
      (s->state.ownshipTime == s->state.received ? hostUs : floodUs).push_back(us);
    }
  });

  UdpSocket sender({"127.0.0.1", 0});
  std::vector<std::uint8_t> host, flood;
  std::uint32_t frame = 0;
  const auto start = Clock::now();
  for (int k = 0; k < 240; ++k) {  // 4 s at 60 Hz
    std::this_thread::sleep_until(start + k * 16667us);
    cigi::IgControl ig;
    ig.hostFrameNumber = ++frame;
    cigi::EntityControl own;
    own.latitudeDeg = 47.0;
    own.longitudeDeg = 11.0;
    own.altitudeM = 1000.0;
    own.yawDeg = static_cast<float>(k % 360);
    const cigi::Packet packets[] = {ig, own};
    ASSERT_EQ(cigi::encodeMessage(packets, protocol::ByteOrder::big, host), "");
    sender.sendTo(host, to);
    if (k % 30 == 15) {  // 2 a second, between the host's frames
      std::vector<cigi::Packet> views{ig};
      for (std::uint16_t id = 0; views.size() < 2046; ++id) views.push_back(viewControl(static_cast<std::uint16_t>(id * 31 + k), 1.0f));
      ASSERT_EQ(cigi::encodeMessage(views, protocol::ByteOrder::big, flood), "");
      ASSERT_GT(flood.size(), 65000u);
      sender.sendTo(flood, to);
    }
  }
  std::this_thread::sleep_for(50ms);
  stopWatch = true;
  watch.join();
  stop = true;
  rx.join();

  ASSERT_GE(hostUs.size(), 200u);  // loopback under load may lose a few; most must arrive
  ASSERT_GE(floodUs.size(), 4u);
  EXPECT_GT(stats.droppedViews.load(), 4u * 1900u);  // ids >= 32 of every flood
  std::sort(hostUs.begin(), hostUs.end());
  std::sort(floodUs.begin(), floodUs.end());
  const double p50 = hostUs[hostUs.size() / 2], p99 = hostUs[hostUs.size() * 99 / 100];
  std::printf("host datagrams: %zu, arrival to visible p50 %.1f us, p99 %.1f us, max %.1f us; "
              "65 KB View Control datagrams: %zu, max %.1f us\n",
              hostUs.size(), p50, p99, hostUs.back(), floodUs.size(), floodUs.back());
  EXPECT_LT(p99, 1000.0);
  EXPECT_LE(latest.get()->state.views.size(), kDefaultMaxViews);
}

// Angles beyond CIGI 3.3's ranges (roll -180..180, pitch -90..90, yaw 0..360, also taken as
// -180..180) are rejected and counted; the last good ownship stays.
TEST(CigiRanges, RollBeyond180AndAbsurdYawAreRejectedAndCounted) {
  CigiStateTracker t;
  cigi::DecodedMessage m;
  cigi::IgControl ig;
  cigi::EntityControl own;
  own.latitudeDeg = 47.0;
  own.longitudeDeg = 11.0;
  own.yawDeg = -90.0f;  // the -180..180 convention
  m.packets = {ig, own};
  EXPECT_EQ(t.apply(m, Clock::now()), 0);
  EXPECT_EQ(t.state().ownship.attitude.yawDeg, -90.0);
  for (const auto& [yaw, roll] : {std::pair{0.0f, 361.0f}, std::pair{3e38f, 0.0f}, std::pair{-181.0f, 0.0f},
                                  std::pair{360.5f, 0.0f}, std::pair{0.0f, -180.5f}}) {
    cigi::EntityControl bad = own;
    bad.yawDeg = yaw;
    bad.rollDeg = roll;
    m.packets = {ig, bad};
    EXPECT_EQ(t.apply(m, Clock::now()), 1) << "yaw " << yaw << " roll " << roll;
    EXPECT_EQ(t.state().ownship.attitude.yawDeg, -90.0);
    EXPECT_EQ(t.state().ownship.attitude.rollDeg, 0.0);
  }
  own.yawDeg = 359.0f;
  own.rollDeg = 180.0f;
  m.packets = {ig, own};
  EXPECT_EQ(t.apply(m, Clock::now()), 0);
  cigi::ViewControl v = viewControl(0, 3e38f);
  m.packets = {ig, v};
  EXPECT_EQ(t.apply(m, Clock::now()), 1);
  v = viewControl(0, 10.0f);
  v.rollEnable = true;
  v.rollDeg = 361.0f;
  m.packets = {ig, v};
  EXPECT_EQ(t.apply(m, Clock::now()), 1);
  EXPECT_EQ(t.state().views.find(0), nullptr);
}

// The first warning at once, then one a interval with the count held back.
TEST(WarningThrottle, FirstThenOneSummaryPerInterval) {
  WarningThrottle w(std::chrono::seconds(5));
  const auto t0 = WarningThrottle::Clock::time_point{} + std::chrono::hours(1);
  std::uint64_t heldBack = 99;
  EXPECT_TRUE(w.allow(t0, &heldBack));
  EXPECT_EQ(heldBack, 0u);
  int logged = 0;
  for (int i = 1; i <= 78 * 12; ++i)  // 78 a second for 12 s
    logged += w.allow(t0 + std::chrono::milliseconds(i * 1000 / 78), &heldBack);
  EXPECT_EQ(logged, 2);  // at 5 s and 10 s
  EXPECT_EQ(heldBack, 78u * 5u - 1u);
}

}  // namespace
}  // namespace skyig::services
