#include "protocol/recording_format.h"

#include <array>
#include <cstdio>

#include "protocol/byte_order.h"
#include "protocol/pcap/pcap_file.h"

namespace skyig::protocol {

const char* toString(RecordingFormat f) {
  switch (f) {
    case RecordingFormat::pcap: return "pcap";
    case RecordingFormat::pcapng: return "pcapng";
    case RecordingFormat::candump: return "candump log";
    case RecordingFormat::unknown: return "unknown";
  }
  return "unknown";
}

RecordingFormat detectRecordingFormat(io::ByteSource& source, std::string* description) {
  std::array<std::uint8_t, 64> b{};
  const std::size_t n = source.readAt(0, b);
  if (n == 0) {
    if (description != nullptr) *description = "empty file";
    return RecordingFormat::unknown;
  }
  if (n >= 4) {
    const std::uint32_t be = loadU32(b.data(), ByteOrder::big);
    const std::uint32_t le = loadU32(b.data(), ByteOrder::little);
    for (std::uint32_t m : {be, le})
      if (m == pcap::kMagicMicro || m == pcap::kMagicNano) return RecordingFormat::pcap;
    if (be == pcap::kPcapngMagic) return RecordingFormat::pcapng;
  }
  std::size_t i = 0;
  while (i < n && (b[i] == ' ' || b[i] == '\t' || b[i] == '\r' || b[i] == '\n')) ++i;
  if (i < n && b[i] == '(') return RecordingFormat::candump;
  if (description != nullptr) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "first bytes %02X %02X %02X %02X", b[0], n > 1 ? b[1] : 0, n > 2 ? b[2] : 0,
                  n > 3 ? b[3] : 0);
    *description = buf;
  }
  return RecordingFormat::unknown;
}

}  // namespace skyig::protocol
