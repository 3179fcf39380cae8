#pragma once
// Reads classic pcap files in either byte order, micro- or nanosecond timestamps. Errors
// name the record (1-based) and the byte offset of its header. With skipBad, a bad record
// is counted and skipped: the reader searches forward for the next plausible record header
// (sane timestamp near the last good one, lengths that fit; with no good one before it,
// eight valid headers following it) and goes on from there.
#include <cstdint>
#include <optional>
#include <vector>

#include "protocol/byte_order.h"
#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcap_file.h"

namespace skyig::protocol::pcap {

struct Record {
  std::uint64_t number = 0;  // 1-based (pcapng: counts packet blocks)
  std::uint64_t offset = 0;  // byte offset of the record header (pcapng: of the block)
  std::int64_t timestampNs = 0;
  std::uint32_t originalLength = 0;
  std::uint32_t linkType = 0;      // of this record (pcapng interfaces may differ)
  std::vector<std::uint8_t> data;  // the captured bytes
};

// What the classic and the pcapng reader have in common; openCapture() picks one.
class CaptureReader {
 public:
  enum class Status : std::uint8_t { record, end, error };
  virtual ~CaptureReader() = default;
  virtual bool open() = 0;
  virtual Status next(Record& out) = 0;
  virtual const RecordError& error() const = 0;
  virtual std::uint64_t skipped() const = 0;
  virtual const std::vector<RecordError>& skippedErrors() const = 0;
};

struct FileHeader {
  ByteOrder byteOrder = ByteOrder::little;
  Precision precision = Precision::micro;
  std::uint16_t versionMajor = 2, versionMinor = 4;
  std::uint32_t snapLength = 0;
  std::uint32_t linkType = 0;
};

class Reader final : public CaptureReader {
 public:
  explicit Reader(io::ByteSource& source, bool skipBad = false) : source_(source), skipBad_(skipBad) {}

  // Reads the file header; false with error() set when it is not a classic pcap file.
  bool open() override;
  const FileHeader& header() const { return header_; }

  // The next record into `out`; Status::end after the last one; Status::error with error()
  // set (without skipBad, or for an I/O error).
  Status next(Record& out) override;

  const RecordError& error() const override { return error_; }
  std::uint64_t skipped() const override { return skipped_; }
  // What was skipped (up to the first 1000), for the log.
  const std::vector<RecordError>& skippedErrors() const override { return skippedErrors_; }

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
