// Decode throughput of the protocol module (not a CTest test: run build/tests/protocol/protocol_bench).
// The headline figure: packets per second through the CIGI decoder for a typical host
// message, IG Control + Entity Control + Celestial Sphere Control (88 bytes).
#include <benchmark/benchmark.h>

#include "protocol/canaerospace/state_decoder.h"
#include "protocol/canaerospace/state_encoder.h"
#include "protocol/cigi/decoder.h"
#include "protocol/cigi/encoder.h"
#include "protocol/io/byte_sink.h"
#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcap_reader.h"
#include "protocol/pcap/pcap_writer.h"

namespace {

using namespace skyig::protocol;

std::vector<std::uint8_t> typicalHostMessage(ByteOrder order) {
  cigi::IgControl ig;
  ig.hostFrameNumber = 1234;
  cigi::EntityControl e;
  e.latitudeDeg = 47.45;
  e.longitudeDeg = 8.56;
  e.altitudeM = 450.0;
  e.yawDeg = 271.0f;
  cigi::CelestialSphereControl c;
  c.hour = 20;
  c.minute = 30;
  c.date = 6212026;
  const std::vector<cigi::Packet> packets{ig, e, c};
  std::vector<std::uint8_t> b;
  cigi::encodeMessage(packets, order, b);
  return b;
}

void BM_CigiDecodeTypicalHostMessage(benchmark::State& state) {
  const auto order = state.range(0) == 0 ? ByteOrder::big : ByteOrder::little;
  const auto msg = typicalHostMessage(order);
  cigi::DecodedMessage d;
  for (auto _ : state) {
    cigi::decodeMessage(msg, d);
    benchmark::DoNotOptimize(d.packets.data());
    if (!d.ok() || d.packets.size() != 3) state.SkipWithError("decode failed");
  }
  state.SetItemsProcessed(state.iterations() * 3);  // packets
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(msg.size()));
  state.SetLabel(order == ByteOrder::big ? "big-endian" : "little-endian");
}
BENCHMARK(BM_CigiDecodeTypicalHostMessage)->Arg(0)->Arg(1);

void BM_CigiEncodeTypicalHostMessage(benchmark::State& state) {
  const auto msg = typicalHostMessage(ByteOrder::little);
  const cigi::DecodedMessage d = cigi::decodeMessage(msg);
  std::vector<std::uint8_t> out;
  for (auto _ : state) {
    cigi::encodeMessage(d.packets, ByteOrder::little, out);
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * 3);
}
BENCHMARK(BM_CigiEncodeTypicalHostMessage);

void BM_CanaerospaceFeed(benchmark::State& state) {
  canaerospace::CanAerospaceState s;
  s.latitudeDeg = 47.45;
  s.longitudeDeg = 8.56;
  canaerospace::StateEncoder enc;
  const std::vector<canaerospace::CanFrame> frames = enc.encode(s);
  canaerospace::StateDecoder dec;
  for (auto _ : state) {
    for (const auto& f : frames) benchmark::DoNotOptimize(dec.feed(f).status);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(frames.size()));  // frames
}
BENCHMARK(BM_CanaerospaceFeed);

void BM_PcapReadRecords(benchmark::State& state) {
  io::MemorySink sink;
  pcap::Writer w(sink);
  w.open();
  const auto msg = typicalHostMessage(ByteOrder::little);
  for (int i = 0; i < 1000; ++i) w.writeUdp(i * 16666667LL, {{10, 0, 0, 1}, 8005}, {{10, 0, 0, 2}, 8004}, msg);
  for (auto _ : state) {
    io::MemorySource src(sink.data);
    pcap::Reader r(src);
    r.open();
    pcap::Record rec;
    while (r.next(rec) == pcap::Reader::Status::record) benchmark::DoNotOptimize(rec.data.data());
  }
  state.SetItemsProcessed(state.iterations() * 1000);  // records
}
BENCHMARK(BM_PcapReadRecords);

}  // namespace

BENCHMARK_MAIN();
