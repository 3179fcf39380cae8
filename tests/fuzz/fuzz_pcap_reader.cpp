// libFuzzer target: any bytes as a capture file (classic pcap or pcapng, chosen by magic),
// read with and without skip-bad, each record's UDP datagram extracted. Must terminate,
// never crash, and keep records inside the file.
#include <cstdint>
#include <cstdlib>
#include <span>

#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcapng_reader.h"
#include "protocol/pcap/udp_frame.h"

using namespace skyig::protocol;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (bool skipBad : {false, true}) {
    io::MemorySource src(std::span(data, size));
    pcap::RecordError err;
    auto reader = pcap::openCapture(src, skipBad, err);
    if (!reader) continue;
    pcap::Record rec;
    std::uint64_t lastEnd = 0;
    while (reader->next(rec) == pcap::CaptureReader::Status::record) {
      // Both formats put at least 16 header bytes before a record's data.
      if (rec.offset < lastEnd || rec.offset + 16 + rec.data.size() > size) std::abort();
      lastEnd = rec.offset + 16 + rec.data.size();
      pcap::UdpDatagram d;
      if (pcap::parseUdpFrame(rec.linkType, rec.data, d) == pcap::FrameError::none) {
        if (d.payload.data() < rec.data.data() || d.payload.data() + d.payload.size() > rec.data.data() + rec.data.size())
          std::abort();
      }
    }
  }
  return 0;
}
