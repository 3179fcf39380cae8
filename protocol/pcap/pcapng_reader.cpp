#include "protocol/pcap/pcapng_reader.h"

#include <algorithm>
#include <array>

namespace skyig::protocol::pcap {

namespace {

// Block types (pcapng draft section 4 and 11.1).
constexpr std::uint32_t kSectionHeader = 0x0A0D0D0Au;
constexpr std::uint32_t kInterfaceDescription = 1;
constexpr std::uint32_t kSimplePacket = 3;
constexpr std::uint32_t kEnhancedPacket = 6;
constexpr std::uint32_t kByteOrderMagic = 0x1A2B3C4Du;
constexpr std::uint16_t kOptionEnd = 0;
constexpr std::uint16_t kOptionTsResolution = 9;
// Largest block skyig reads: a packet block of the biggest record plus generous options.
constexpr std::uint32_t kMaxBlock = kMaxRecordLength + 65536;

std::string where(std::uint64_t packet, std::uint64_t offset) {
  return "block at byte " + std::to_string(offset) + " (after packet " + std::to_string(packet) + ")";
}

std::uint32_t padded4(std::uint32_t n) { return (n + 3u) & ~3u; }

}  // namespace

PcapngReader::Status PcapngReader::fail(RecordError e) {
  error_ = std::move(e);
  failed_ = true;
  return Status::error;
}

bool PcapngReader::readSectionHeader(std::uint64_t offset, RecordError& err) {
  std::array<std::uint8_t, 16> h{};
  if (source_.readAt(offset, h) < h.size()) {
    err = {RecordError::Kind::truncatedRecordHeader, packets_, offset,
           "truncated pcapng file: section header at byte " + std::to_string(offset) + " is cut short"};
    return false;
  }
  if (loadU32(&h[8], ByteOrder::big) == kByteOrderMagic)
    order_ = ByteOrder::big;
  else if (loadU32(&h[8], ByteOrder::little) == kByteOrderMagic)
    order_ = ByteOrder::little;
  else {
    err = {RecordError::Kind::notPcap, packets_, offset,
           "corrupt pcapng section header at byte " + std::to_string(offset) + ": byte-order magic missing"};
    return false;
  }
  const std::uint16_t major = loadU16(&h[12], order_);
  if (major != 1) {
    err = {RecordError::Kind::unsupportedVersion, packets_, offset,
           "pcapng section at byte " + std::to_string(offset) + " has version " + std::to_string(major) +
               ", expected 1"};
    return false;
  }
  interfaces_.clear();  // interface ids are per section
  return true;
}

bool PcapngReader::readInterface(const std::vector<std::uint8_t>& body, std::uint64_t offset, RecordError& err) {
  if (body.size() < 8) {
    err = {RecordError::Kind::badRecordHeader, packets_, offset,
           "corrupt pcapng interface description " + where(packets_, offset) + ": too short"};
    return false;
  }
  Interface i;
  i.linkType = loadU16(&body[0], order_);
  i.snapLength = loadU32(&body[4], order_);
  // Options: code, length, value padded to 4 bytes, until opt_endofopt.
  std::size_t p = 8;
  while (p + 4 <= body.size()) {
    const std::uint16_t code = loadU16(&body[p], order_);
    const std::uint16_t len = loadU16(&body[p + 2], order_);
    if (code == kOptionEnd) break;
    if (p + 4 + len > body.size()) break;  // a malformed option list ends the options
    if (code == kOptionTsResolution && len >= 1) {
      i.binaryResolution = (body[p + 4] & 0x80) != 0;
      i.exponent = static_cast<std::uint8_t>(body[p + 4] & 0x7F);
    }
    p += 4 + padded4(len);
  }
  interfaces_.push_back(i);
  return true;
}

std::int64_t PcapngReader::toNanoseconds(const Interface& i, std::uint64_t ticks) const {
  if (!i.binaryResolution) {
    if (i.exponent <= 9) {
      std::uint64_t scale = 1;
      for (int k = i.exponent; k < 9; ++k) scale *= 10;
      return static_cast<std::int64_t>(ticks * scale);
    }
    std::uint64_t divisor = 1;
    for (int k = 9; k < i.exponent && k < 28; ++k) divisor *= 10;
    return static_cast<std::int64_t>(ticks / divisor);
  }
  // 2^-exponent seconds: whole seconds, then the fraction (exponent <= 32 keeps it in 64 bits).
  const unsigned e = i.exponent > 32 ? 32 : i.exponent;
  const std::uint64_t seconds = ticks >> e;
  const std::uint64_t fraction = ticks & ((std::uint64_t{1} << e) - 1);
  return static_cast<std::int64_t>(seconds * 1000000000ull + ((fraction * 1000000000ull) >> e));
}

bool PcapngReader::open() {
  std::array<std::uint8_t, 8> h{};
  const std::size_t n = source_.readAt(0, h);
  if (n < 8 || loadU32(h.data(), ByteOrder::big) != kSectionHeader) {
    error_ = {RecordError::Kind::notPcap, 0, 0, "not a pcapng file: no section header block at byte 0"};
    return false;
  }
  offset_ = 0;
  return true;
}

PcapngReader::BlockResult PcapngReader::readBlock(Record& out, RecordError& err) {
  const std::uint64_t size = source_.size();
  const std::uint64_t at = offset_;
  if (at >= size) return BlockResult::end;
  std::array<std::uint8_t, 8> h{};
  const std::size_t n = source_.readAt(at, h);
  if (n < 8) {
    err = {RecordError::Kind::truncatedRecordHeader, packets_ + 1, at,
           "truncated pcapng file: " + where(packets_, at) + " has " + std::to_string(n) + " of 8 header bytes"};
    return BlockResult::bad;
  }
  // The section header's type reads the same in both orders; its length needs the order
  // that its byte-order magic announces.
  std::uint32_t type = loadU32(&h[0], order_);
  if (loadU32(&h[0], ByteOrder::big) == kSectionHeader) {
    std::array<std::uint8_t, 4> magic{};
    if (source_.readAt(at + 8, magic) == 4)
      order_ = loadU32(magic.data(), ByteOrder::big) == kByteOrderMagic ? ByteOrder::big : ByteOrder::little;
    type = kSectionHeader;
  }
  const std::uint32_t length = loadU32(&h[4], order_);
  if (length < 12 || length % 4 != 0 || length > kMaxBlock) {
    err = {RecordError::Kind::badRecordHeader, packets_ + 1, at,
           "corrupt pcapng " + where(packets_, at) + ": block length " + std::to_string(length) +
               " (must be a multiple of 4 between 12 and " + std::to_string(kMaxBlock) + ")"};
    return BlockResult::bad;
  }
  if (length > size - at) {
    err = {RecordError::Kind::truncatedRecord, packets_ + 1, at,
           "truncated pcapng file: " + where(packets_, at) + " claims " + std::to_string(length) +
               " bytes but the file ends " + std::to_string(size - at) + " bytes after its start"};
    return BlockResult::bad;
  }
  body_.resize(length - 12);
  std::array<std::uint8_t, 4> tail{};
  if (source_.readAt(at + 8, body_) != body_.size() || source_.readAt(at + length - 4, tail) != 4) {
    err = {RecordError::Kind::io, packets_ + 1, at, "reading " + where(packets_, at) + ": " + source_.error()};
    return BlockResult::bad;
  }
  if (loadU32(tail.data(), order_) != length) {
    err = {RecordError::Kind::badRecordHeader, packets_ + 1, at,
           "corrupt pcapng " + where(packets_, at) + ": trailing length " +
               std::to_string(loadU32(tail.data(), order_)) + " differs from the leading " + std::to_string(length)};
    return BlockResult::bad;
  }
  offset_ = at + length;
  switch (type) {
    case kSectionHeader: return readSectionHeader(at, err) ? BlockResult::other : BlockResult::bad;
    case kInterfaceDescription: return readInterface(body_, at, err) ? BlockResult::other : BlockResult::bad;
    case kEnhancedPacket: {
      if (body_.size() < 20) {
        err = {RecordError::Kind::badRecordHeader, packets_ + 1, at,
               "corrupt pcapng " + where(packets_, at) + ": enhanced packet block too short"};
        return BlockResult::bad;
      }
      const std::uint32_t ifId = loadU32(&body_[0], order_);
      const std::uint64_t ticks =
          (static_cast<std::uint64_t>(loadU32(&body_[4], order_)) << 32) | loadU32(&body_[8], order_);
      const std::uint32_t captured = loadU32(&body_[12], order_);
      const std::uint32_t original = loadU32(&body_[16], order_);
      if (ifId >= interfaces_.size() || captured > body_.size() - 20 || captured > kMaxRecordLength) {
        err = {RecordError::Kind::badRecordHeader, packets_ + 1, at,
               "corrupt pcapng " + where(packets_, at) + ": interface " + std::to_string(ifId) + " of " +
                   std::to_string(interfaces_.size()) + ", captured length " + std::to_string(captured) +
                   " in a block of " + std::to_string(length) + " bytes"};
        return BlockResult::bad;
      }
      out.timestampNs = toNanoseconds(interfaces_[ifId], ticks);
      out.originalLength = original;
      out.linkType = interfaces_[ifId].linkType;
      out.data.assign(body_.begin() + 20, body_.begin() + 20 + captured);
      break;
    }
    case kSimplePacket: {
      if (interfaces_.empty() || body_.size() < 4) {
        err = {RecordError::Kind::badRecordHeader, packets_ + 1, at,
               "corrupt pcapng " + where(packets_, at) + ": simple packet block without an interface"};
        return BlockResult::bad;
      }
      const std::uint32_t original = loadU32(&body_[0], order_);
      std::uint32_t captured = std::min<std::uint32_t>(original, static_cast<std::uint32_t>(body_.size() - 4));
      if (interfaces_[0].snapLength != 0) captured = std::min(captured, interfaces_[0].snapLength);
      out.timestampNs = 0;  // simple packet blocks carry no time
      out.originalLength = original;
      out.linkType = interfaces_[0].linkType;
      out.data.assign(body_.begin() + 4, body_.begin() + 4 + captured);
      break;
    }
    default: return BlockResult::other;  // statistics, name resolution, custom blocks...
  }
  ++packets_;
  out.number = packets_;
  out.offset = at;
  return BlockResult::packet;
}

bool PcapngReader::plausibleBlockAt(std::uint64_t offset) {
  std::array<std::uint8_t, 8> h{};
  if (source_.readAt(offset, h) < 8) return false;
  const std::uint32_t type = loadU32(&h[0], order_);
  const std::uint32_t length = loadU32(&h[4], order_);
  const bool knownType = type == kSectionHeader || type == kInterfaceDescription || type == kSimplePacket ||
                         type == kEnhancedPacket || (type >= 2 && type <= 10);
  if (!knownType || length < 12 || length % 4 != 0 || length > kMaxBlock || length > source_.size() - offset)
    return false;
  std::array<std::uint8_t, 4> tail{};
  return source_.readAt(offset + length - 4, tail) == 4 && loadU32(tail.data(), order_) == length;
}

PcapngReader::Status PcapngReader::next(Record& out) {
  if (failed_) return Status::error;
  while (true) {
    RecordError err;
    const std::uint64_t at = offset_;
    switch (readBlock(out, err)) {
      case BlockResult::packet: return Status::record;
      case BlockResult::end: return Status::end;
      case BlockResult::other: continue;
      case BlockResult::bad: {
        if (!skipBad_ || err.kind == RecordError::Kind::io || err.kind == RecordError::Kind::unsupportedVersion)
          return fail(std::move(err));
        ++skipped_;
        if (skippedErrors_.size() < 1000) skippedErrors_.push_back(err);
        std::uint64_t p = at + 4;  // blocks are 4-byte aligned
        while (p + 12 <= source_.size() && !plausibleBlockAt(p)) p += 4;
        offset_ = p + 12 <= source_.size() ? p : source_.size();
        continue;
      }
    }
  }
}

std::unique_ptr<CaptureReader> openCapture(io::ByteSource& source, bool skipBad, RecordError& error) {
  std::array<std::uint8_t, 4> magic{};
  std::unique_ptr<CaptureReader> r;
  if (source.readAt(0, magic) == 4 && loadU32(magic.data(), ByteOrder::big) == kPcapngMagic)
    r = std::make_unique<PcapngReader>(source, skipBad);
  else
    r = std::make_unique<Reader>(source, skipBad);
  if (!r->open()) {
    error = r->error();
    return nullptr;
  }
  return r;
}

}  // namespace skyig::protocol::pcap
