#pragma once
// Reads classic pcap files in either byte order, micro- or nanosecond timestamps. Errors
// name the record (1-based) and the byte offset of its header. With skipBad, a bad record
// is counted and skipped: the reader searches forward for the next plausible record header
// (sane timestamp near the last good one, lengths that fit) and goes on from there.
#include <cstdint>
#include <optional>
#include <vector>

#include "protocol/byte_order.h"
#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcap_file.h"

namespace skyig::protocol::pcap {

struct Record {
  std::uint64_t number = 0;  // 1-based
  std::uint64_t offset = 0;  // byte offset of the record header
  std::int64_t timestampNs = 0;
  std::uint32_t originalLength = 0;
  std::vector<std::uint8_t> data;  // the captured bytes
};

struct FileHeader {
  ByteOrder byteOrder = ByteOrder::little;
  Precision precision = Precision::micro;
  std::uint16_t versionMajor = 2, versionMinor = 4;
  std::uint32_t snapLength = 0;
  std::uint32_t linkType = 0;
};

class Reader {
 public:
  enum class Status : std::uint8_t { record, end, error };

  explicit Reader(io::ByteSource& source, bool skipBad = false) : source_(source), skipBad_(skipBad) {}

  // Reads the file header; false with error() set when it is not a classic pcap file.
  bool open();
  const FileHeader& header() const { return header_; }

  // The next record into `out`; Status::end after the last one; Status::error with error()
  // set (without skipBad, or for an I/O error).
  Status next(Record& out);

  const RecordError& error() const { return error_; }
  std::uint64_t skipped() const { return skipped_; }
  // What was skipped (up to the first 1000), for the log.
  const std::vector<RecordError>& skippedErrors() const { return skippedErrors_; }

 private:
  // Checks the record header at `offset`; nullopt when it is a plausible header. Without
  // `withMessage` the error carries only its kind (cheap, for resynchronisation scans).
  std::optional<RecordError> checkRecordHeader(std::uint64_t offset, std::uint64_t number, std::uint32_t* captured,
                                               std::int64_t* timestampNs, bool withMessage = true);
  bool plausibleAt(std::uint64_t offset);
  std::optional<std::uint64_t> resynchronise(std::uint64_t from);
  Status fail(RecordError e);

  io::ByteSource& source_;
  bool skipBad_;
  FileHeader header_;
  RecordError error_;
  std::uint64_t offset_ = kFileHeaderSize;
  std::uint64_t number_ = 0;
  std::uint64_t skipped_ = 0;
  bool failed_ = false;
  std::optional<std::int64_t> lastTimestampNs_;
  std::vector<RecordError> skippedErrors_;
};

}  // namespace skyig::protocol::pcap
