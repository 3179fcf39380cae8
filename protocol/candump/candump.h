#pragma once
// The can-utils log format written by `candump -l` / `-L` and read by `canplayer`
// (can-utils lib.c, sprint_canframe/parse_canframe):
//   (1700000000.123456) can0 123#DEADBEEF
// seconds and microseconds of the receive time, the interface, then the frame: 3 hex digits
// for an 11-bit identifier, 8 for a 29-bit one (or an error frame, flag 0x20000000 in the
// digits), '#', and the data as hex pairs ('.' separators allowed); `#R` (optionally
// followed by a length digit) marks a remote frame. CAN FD (`##`) is rejected by name.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/canaerospace/can_frame.h"
#include "protocol/io/byte_sink.h"
#include "protocol/io/byte_source.h"

namespace skyig::protocol::candump {

using canaerospace::CanFrame;

struct Record {
  std::uint64_t line = 0;    // 1-based line number
  std::uint64_t offset = 0;  // byte offset of the line
  std::int64_t timestampUs = 0;
  std::string interface;
  CanFrame frame;
};

struct LineError {
  std::uint64_t line = 0;
  std::uint64_t offset = 0;
  std::string message;  // names the line, the offset and what could not be parsed
};

// Parses one line (without its newline). nullopt and `why` set when it does not parse.
std::optional<Record> parseLine(std::string_view line, std::string* why);

// Formats one record as candump -l does, with the trailing newline.
std::string formatLine(std::int64_t timestampUs, std::string_view interface, const CanFrame& frame);

class Reader {
 public:
  enum class Status : std::uint8_t { record, end, error };
  explicit Reader(io::ByteSource& source, bool skipBad = false) : source_(source), skipBad_(skipBad) {}

  // Blank lines are skipped; any other line that does not parse is an error (or, with
  // skipBad, counted and skipped).
  Status next(Record& out);
  const LineError& error() const { return error_; }
  std::uint64_t skipped() const { return skipped_; }
  const std::vector<LineError>& skippedErrors() const { return skippedErrors_; }

 private:
  bool readLine(std::string& line, std::uint64_t& lineOffset);

  io::ByteSource& source_;
  bool skipBad_;
  std::uint64_t offset_ = 0;
  std::uint64_t line_ = 0;
  std::uint64_t skipped_ = 0;
  LineError error_;
  std::vector<LineError> skippedErrors_;
  std::vector<std::uint8_t> chunk_;
  std::size_t chunkPos_ = 0;
  std::uint64_t chunkOffset_ = 0;
};

// Writes one line per frame; each line goes to the sink in a single write, so the log ends
// with a complete line after a crash (flush policy: protocol/io/byte_sink.h).
class Writer {
 public:
  explicit Writer(io::ByteSink& sink, std::uint32_t syncEveryRecords = 0)
      : sink_(sink), syncEvery_(syncEveryRecords) {}
  bool write(std::int64_t timestampUs, std::string_view interface, const CanFrame& frame);
  const std::string& error() const { return error_; }
  std::uint64_t records() const { return records_; }

 private:
  io::ByteSink& sink_;
  std::uint32_t syncEvery_;
  std::string error_;
  std::uint64_t records_ = 0;
};

}  // namespace skyig::protocol::candump
