#include "protocol/pcap/pcap_reader.h"

#include <array>
#include <cstdio>

namespace skyig::protocol::pcap {

namespace {

std::string where(std::uint64_t number, std::uint64_t offset) {
  return "record " + std::to_string(number) + " at byte " + std::to_string(offset);
}

RecordError makeError(RecordError::Kind kind, std::uint64_t number, std::uint64_t offset, std::string message) {
  return RecordError{kind, number, offset, std::move(message)};
}

// How far from the last good record a candidate header's time may lie when resynchronising.
constexpr std::int64_t kResyncWindowNs = 86400LL * 1000000000LL;
// How many following records must also read as records when no good record came before.
constexpr int kResyncChainWithoutAnchor = 8;

}  // namespace

bool Reader::open() {
  std::array<std::uint8_t, kFileHeaderSize> h{};
  const std::size_t n = source_.readAt(0, h);
  if (!source_.error().empty()) {
    error_ = makeError(RecordError::Kind::io, 0, 0, source_.error());
    return false;
  }
  if (n == 0) {
    error_ = makeError(RecordError::Kind::notPcap, 0, 0, "not a pcap file: the file is empty");
    return false;
  }
  if (n >= 4) {
    const std::uint32_t be = loadU32(h.data(), ByteOrder::big);
    const std::uint32_t le = loadU32(h.data(), ByteOrder::little);
    if (be == kMagicMicro || be == kMagicNano) {
      header_.byteOrder = ByteOrder::big;
      header_.precision = be == kMagicNano ? Precision::nano : Precision::micro;
    } else if (le == kMagicMicro || le == kMagicNano) {
      header_.byteOrder = ByteOrder::little;
      header_.precision = le == kMagicNano ? Precision::nano : Precision::micro;
    } else {
      char buf[160];
      std::snprintf(buf, sizeof buf, "not a pcap file: magic %02X %02X %02X %02X at byte 0", h[0], h[1], h[2], h[3]);
      std::string m = buf;
      if (be == kPcapngMagic)
        m += " is pcapng: read it with pcap::openCapture or PcapngReader";
      else if (be == 0xA1B2CD34u || le == 0xA1B2CD34u)
        m += " is the modified (Kuznetzov) pcap format: convert it with `editcap -F pcap IN OUT`";
      else if (h[0] == '(')
        m += " looks like text (a candump log?)";
      else
        m += ", expected A1 B2 C3 D4 or A1 B2 3C 4D in either byte order";
      error_ = makeError(RecordError::Kind::notPcap, 0, 0, m);
      return false;
    }
  } else {
    error_ = makeError(RecordError::Kind::notPcap, 0, 0,
                       "not a pcap file: " + std::to_string(n) + " bytes, too short for a magic number");
    return false;
  }
  if (n < kFileHeaderSize) {
    error_ = makeError(RecordError::Kind::truncatedHeader, 0, 0,
                       "truncated pcap file: " + std::to_string(n) + " of the 24 file-header bytes");
    return false;
  }
  const ByteOrder o = header_.byteOrder;
  header_.versionMajor = loadU16(&h[4], o);
  header_.versionMinor = loadU16(&h[6], o);
  header_.snapLength = loadU32(&h[16], o);
  // The top bits of the link-type word hold FCS information (pcap-savefile(5)).
  header_.linkType = loadU32(&h[20], o) & 0x0FFFFFFFu;
  if (header_.versionMajor != 2) {
    error_ = makeError(RecordError::Kind::unsupportedVersion, 0, 4,
                       "pcap version " + std::to_string(header_.versionMajor) + "." +
                           std::to_string(header_.versionMinor) + " at byte 4, expected 2.x");
    return false;
  }
  offset_ = kFileHeaderSize;
  number_ = 0;
  return true;
}

std::optional<RecordError> Reader::checkRecordHeader(std::uint64_t offset, std::uint64_t number,
                                                     std::uint32_t* captured, std::int64_t* timestampNs,
                                                     bool withMessage) {
  const std::uint64_t size = source_.size();
  // Messages are only formatted when wanted: resynchronisation checks every byte offset.
  const auto fault = [&](RecordError::Kind kind, auto&& message) {
    return withMessage ? RecordError{kind, number, offset, message()} : RecordError{kind, number, offset, {}};
  };
  std::array<std::uint8_t, kRecordHeaderSize> h{};
  const std::size_t n = offset < size ? source_.readAt(offset, h) : 0;
  if (!source_.error().empty()) return fault(RecordError::Kind::io, [&] { return source_.error(); });
  if (n < kRecordHeaderSize)
    return fault(RecordError::Kind::truncatedRecordHeader, [&] {
      return "truncated pcap file: " + where(number, offset) + " has " + std::to_string(n) + " of 16 header bytes";
    });
  const ByteOrder o = header_.byteOrder;
  const std::uint32_t seconds = loadU32(&h[0], o);
  const std::uint32_t fraction = loadU32(&h[4], o);
  const std::uint32_t incl = loadU32(&h[8], o);
  const std::uint32_t orig = loadU32(&h[12], o);
  const std::uint32_t fractionLimit = header_.precision == Precision::nano ? 1000000000u : 1000000u;
  if (fraction >= fractionLimit)
    return fault(RecordError::Kind::badRecordHeader, [&] {
      return "corrupt pcap " + where(number, offset) + ": sub-second field " + std::to_string(fraction) +
             " is not below " + std::to_string(fractionLimit);
    });
  if (incl > kMaxRecordLength)
    return fault(RecordError::Kind::recordTooLong, [&] {
      return "corrupt pcap " + where(number, offset) + ": captured length " + std::to_string(incl) + " exceeds " +
             std::to_string(kMaxRecordLength) + " bytes";
    });
  if (incl > orig)
    return fault(RecordError::Kind::badRecordHeader, [&] {
      return "corrupt pcap " + where(number, offset) + ": captured length " + std::to_string(incl) +
             " exceeds the original length " + std::to_string(orig);
    });
  if (incl > size - offset - kRecordHeaderSize)
    return fault(RecordError::Kind::truncatedRecord, [&] {
      return "truncated pcap file: " + where(number, offset) + " claims " + std::to_string(incl) +
             " bytes but the file ends " + std::to_string(size - offset - kRecordHeaderSize) +
             " bytes after its header";
    });
  *captured = incl;
  *timestampNs = static_cast<std::int64_t>(seconds) * 1000000000LL +
                 static_cast<std::int64_t>(fraction) * (header_.precision == Precision::nano ? 1 : 1000);
  return std::nullopt;
}

bool Reader::plausibleAt(std::uint64_t offset) {
  std::uint32_t incl = 0;
  std::int64_t ts = 0;
  if (checkRecordHeader(offset, 0, &incl, &ts, false)) return false;
  // Near the last good record's time; before any good record (the first one is corrupt),
  // near this candidate's own.
  const std::int64_t anchor = lastTimestampNs_.value_or(ts);
  if (ts < anchor - kResyncWindowNs || ts > anchor + kResyncWindowNs) return false;
  // The records after it must fit too (or the file ends right there): one after a good record,
  // kResyncChainWithoutAnchor without one, since any 16 bytes of zeros inside a frame read as an
  // empty record at time 0 and a chain of them as more.
  const int chain = lastTimestampNs_ ? 1 : kResyncChainWithoutAnchor;
  std::uint64_t next = offset + kRecordHeaderSize + incl;
  for (int k = 0; k < chain; ++k) {
    if (next == source_.size()) return true;
    std::uint32_t incl2 = 0;
    std::int64_t ts2 = 0;
    if (checkRecordHeader(next, 0, &incl2, &ts2, false).has_value()) return false;
    if (ts2 < anchor - kResyncWindowNs || ts2 > anchor + kResyncWindowNs) return false;
    next += kRecordHeaderSize + incl2;
  }
  return true;
}

std::optional<std::uint64_t> Reader::resynchronise(std::uint64_t from) {
  const std::uint64_t size = source_.size();
  for (std::uint64_t p = from; p + kRecordHeaderSize <= size; ++p)
    if (plausibleAt(p)) return p;
  return std::nullopt;
}

Reader::Status Reader::fail(RecordError e) {
  error_ = std::move(e);
  failed_ = true;  // a failed reader keeps answering with its error
  return Status::error;
}

Reader::Status Reader::next(Record& out) {
  if (failed_) return Status::error;
  while (offset_ < source_.size()) {
    const std::uint64_t number = number_ + 1;
    std::uint32_t incl = 0;
    std::int64_t ts = 0;
    if (auto err = checkRecordHeader(offset_, number, &incl, &ts)) {
      if (!skipBad_ || err->kind == RecordError::Kind::io) return fail(std::move(*err));
      ++skipped_;
      if (skippedErrors_.size() < 1000) skippedErrors_.push_back(*err);
      number_ = number;
      const std::optional<std::uint64_t> resume = resynchronise(offset_ + 1);
      offset_ = resume.value_or(source_.size());
      continue;
    }
    out.data.resize(incl);
    const std::size_t got = source_.readAt(offset_ + kRecordHeaderSize, out.data);
    if (got != incl)
      return fail(makeError(RecordError::Kind::io, number, offset_,
                            "reading " + where(number, offset_) + ": " +
                                (source_.error().empty() ? std::string("short read") : source_.error())));
    std::array<std::uint8_t, kRecordHeaderSize> h{};
    source_.readAt(offset_, h);
    out.number = number;
    out.offset = offset_;
    out.timestampNs = ts;
    out.originalLength = loadU32(&h[12], header_.byteOrder);
    out.linkType = header_.linkType;
    number_ = number;
    lastTimestampNs_ = ts;
    offset_ += kRecordHeaderSize + incl;
    return Status::record;
  }
  return Status::end;
}

}  // namespace skyig::protocol::pcap
