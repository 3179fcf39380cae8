#pragma once
// Writes classic pcap: the file header when opened, then one record per captured datagram,
// each handed to the sink in a single write (flush policy: protocol/io/byte_sink.h and
// docs/protocol.md). UDP payloads are wrapped in Ethernet/IPv4/UDP (or raw IPv4) headers so
// Wireshark, tshark and tcpdump read the file as ordinary UDP traffic.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "protocol/byte_order.h"
#include "protocol/io/byte_sink.h"
#include "protocol/pcap/pcap_file.h"
#include "protocol/pcap/udp_frame.h"

namespace skyig::protocol::pcap {

struct WriterOptions {
  std::uint32_t linkType = kLinkEthernet;  // kLinkEthernet, kLinkRaw or kLinkIpv4
  Precision precision = Precision::micro;
  ByteOrder byteOrder = nativeByteOrder();  // as libpcap writes
  // libpcap's own default (262144): holds any UDP datagram over IPv4 (65,507 bytes of payload
  // plus its link, IP and UDP headers), so `record` never has to cut one. A longer frame is cut
  // to the snap length with its original length in the record header, and counted (truncated()).
  std::uint32_t snapLength = kMaxRecordLength;
  // Call the sink's sync() every this many records (0: never; the sink's writes already
  // reach the kernel per record). A sink whose sync() is fdatasync bounds power-loss damage.
  std::uint32_t syncEveryRecords = 0;
};

class Writer {
 public:
  Writer(io::ByteSink& sink, WriterOptions options = {}) : sink_(sink), options_(options) {}

  // Writes the file header; false with error() on failure.
  bool open();
  // One record of raw link-layer bytes captured at `timestampNs` (ns since the Unix epoch,
  // >= 0). `originalLength` 0 means frame.size(). Bytes beyond the snap length are not
  // written (the record says how long the frame was), as tcpdump does.
  bool writeRecord(std::int64_t timestampNs, std::span<const std::uint8_t> frame, std::uint32_t originalLength = 0);
  // One UDP datagram, wrapped in headers of the writer's link type.
  bool writeUdp(std::int64_t timestampNs, const Endpoint& source, const Endpoint& destination,
                std::span<const std::uint8_t> payload);

  const std::string& error() const { return error_; }
  std::uint64_t records() const { return records_; }
  std::uint64_t truncated() const { return truncated_; }  // records cut to the snap length

 private:
  bool fail(std::string message);

  io::ByteSink& sink_;
  WriterOptions options_;
  std::string error_;
  std::uint64_t records_ = 0;
  std::uint64_t truncated_ = 0;
  std::uint16_t ipId_ = 0;
  std::vector<std::uint8_t> buffer_;
  std::vector<std::uint8_t> frame_;
};

}  // namespace skyig::protocol::pcap
