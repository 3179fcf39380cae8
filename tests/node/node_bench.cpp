// Latency of the receive path: a typical host datagram (IG Control, Entity Control, Rate
// Control, Celestial Sphere Control, Atmosphere Control) decoded, applied and published, then
// fetched as the render thread does. Not part of ctest: run build/tests/node/node_bench.
#include "protocol/cigi/date.h"
#include "protocol/cigi/encoder.h"
#include "node/transport/cigi_receiver.h"

#include <benchmark/benchmark.h>

using namespace skyig::services;
namespace cigi = skyig::protocol::cigi;

static void BM_DatagramToVisible(benchmark::State& state) {
  NodeStats stats;
  Latest<HostSnapshot> latest;
  CigiReceiver receiver(stats, latest);
  cigi::IgControl ig;
  cigi::EntityControl e;
  e.latitudeDeg = 47.26;
  e.longitudeDeg = 11.34;
  cigi::RateControl r;
  r.xRateMps = 40.0f;
  cigi::CelestialSphereControl cs;
  cs.date = *cigi::composeDate({2026, 6, 21});
  cigi::AtmosphereControl a;
  std::vector<std::uint8_t> bytes;
  const Sender from{0x7F000001u, 9};  // 127.0.0.1:9
  std::uint32_t frame = 0;
  for (auto _ : state) {
    ig.hostFrameNumber = ++frame;
    e.yawDeg = static_cast<float>(frame % 360);
    const cigi::Packet packets[] = {ig, e, r, cs, a};
    state.PauseTiming();
    cigi::encodeMessage(packets, skyig::protocol::ByteOrder::big, bytes);
    state.ResumeTiming();
    receiver.handle(bytes, from, Clock::now());
    const auto seen = latest.get();  // what the render thread does at the start of a frame
    benchmark::DoNotOptimize(seen->state.ownship.attitude.yawDeg);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_DatagramToVisible);

BENCHMARK_MAIN();
