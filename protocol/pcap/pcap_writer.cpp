#include "protocol/pcap/pcap_writer.h"

#include <algorithm>

namespace skyig::protocol::pcap {

bool Writer::fail(std::string message) {
  error_ = std::move(message);
  return false;
}

bool Writer::open() {
  if (options_.linkType != kLinkEthernet && options_.linkType != kLinkRaw && options_.linkType != kLinkIpv4)
    return fail("pcap writer: link type " + std::to_string(options_.linkType) + " (" +
                linkTypeName(options_.linkType) + ") not supported: use ETHERNET (1), RAW (101) or IPV4 (228)");
  std::uint8_t h[kFileHeaderSize] = {};
  const ByteOrder o = options_.byteOrder;
  storeU32(h + 0, options_.precision == Precision::nano ? kMagicNano : kMagicMicro, o);
  storeU16(h + 4, 2, o);   // version major
  storeU16(h + 6, 4, o);   // version minor
  storeU32(h + 8, 0, o);   // thiszone: timestamps are UTC
  storeU32(h + 12, 0, o);  // sigfigs
  storeU32(h + 16, options_.snapLength, o);
  storeU32(h + 20, options_.linkType, o);
  if (!sink_.write(h)) return fail("pcap writer: file header: " + sink_.error());
  return true;
}

bool Writer::writeRecord(std::int64_t timestampNs, std::span<const std::uint8_t> frame, std::uint32_t originalLength) {
  if (!error_.empty()) return false;
  if (timestampNs < 0) return fail("pcap writer: negative timestamp " + std::to_string(timestampNs) + " ns");
  if (frame.size() > 0xFFFFFFFFu) return fail("pcap writer: record of " + std::to_string(frame.size()) + " bytes");
  if (originalLength == 0) originalLength = static_cast<std::uint32_t>(frame.size());
  if (frame.size() > options_.snapLength) {
    frame = frame.first(options_.snapLength);
    ++truncated_;
  }
  const auto seconds = static_cast<std::uint64_t>(timestampNs / 1000000000);
  if (seconds > 0xFFFFFFFFu) return fail("pcap writer: timestamp " + std::to_string(timestampNs) + " ns after 2106");
  const auto ns = static_cast<std::uint32_t>(timestampNs % 1000000000);
  const std::uint32_t fraction = options_.precision == Precision::nano ? ns : ns / 1000u;
  const auto captured = static_cast<std::uint32_t>(frame.size());
  buffer_.resize(kRecordHeaderSize + frame.size());
  const ByteOrder o = options_.byteOrder;
  storeU32(buffer_.data() + 0, static_cast<std::uint32_t>(seconds), o);
  storeU32(buffer_.data() + 4, fraction, o);
  storeU32(buffer_.data() + 8, captured, o);
  storeU32(buffer_.data() + 12, std::max(originalLength, captured), o);
  std::copy(frame.begin(), frame.end(), buffer_.begin() + kRecordHeaderSize);
  if (!sink_.write(buffer_)) return fail("pcap writer: record " + std::to_string(records_ + 1) + ": " + sink_.error());
  ++records_;
  if (options_.syncEveryRecords != 0 && records_ % options_.syncEveryRecords == 0 && !sink_.sync())
    return fail("pcap writer: sync after record " + std::to_string(records_) + ": " + sink_.error());
  return true;
}

bool Writer::writeUdp(std::int64_t timestampNs, const Endpoint& source, const Endpoint& destination,
                      std::span<const std::uint8_t> payload) {
  if (!error_.empty()) return false;
  std::string err = buildUdpFrame(options_.linkType, source, destination, payload, ipId_++, frame_);
  if (!err.empty()) return fail("pcap writer: " + err);
  return writeRecord(timestampNs, frame_);
}

}  // namespace skyig::protocol::pcap
