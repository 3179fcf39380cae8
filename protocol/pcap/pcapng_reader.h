#pragma once
// Reads pcapng files (draft-ietf-opsawg-pcapng), what Wireshark, tshark and dumpcap write by
// default: Section Header Blocks (byte order per section), Interface Description Blocks
// (link type, snap length, if_tsresol), Enhanced and Simple Packet Blocks; every other
// block is skipped by its length. Errors name the packet number and the block's byte offset;
// with skipBad a bad block is counted and the reader searches forward for the next block
// whose leading and trailing lengths agree.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "protocol/byte_order.h"
#include "protocol/io/byte_source.h"
#include "protocol/pcap/pcap_reader.h"

namespace skyig::protocol::pcap {

class PcapngReader final : public CaptureReader {
 public:
  explicit PcapngReader(io::ByteSource& source, bool skipBad = false) : source_(source), skipBad_(skipBad) {}

  bool open() override;  // checks the first Section Header Block
  Status next(Record& out) override;
  const RecordError& error() const override { return error_; }
  std::uint64_t skipped() const override { return skipped_; }
  const std::vector<RecordError>& skippedErrors() const override { return skippedErrors_; }

 private:
  struct Interface {
    std::uint32_t linkType = 0;
    std::uint32_t snapLength = 0;
    bool binaryResolution = false;  // if_tsresol: 2^-exponent instead of 10^-exponent
    std::uint8_t exponent = 6;      // default: microseconds
  };
  enum class BlockResult : std::uint8_t { packet, other, bad, end };

  BlockResult readBlock(Record& out, RecordError& err);
  bool readSectionHeader(std::uint64_t offset, RecordError& err);
  bool readInterface(const std::vector<std::uint8_t>& body, std::uint64_t offset, RecordError& err);
  std::int64_t toNanoseconds(const Interface& i, std::uint64_t ticks) const;
  bool plausibleBlockAt(std::uint64_t offset);
  Status fail(RecordError e);

  io::ByteSource& source_;
  bool skipBad_;
  ByteOrder order_ = ByteOrder::little;
  std::vector<Interface> interfaces_;
  std::uint64_t offset_ = 0;
  std::uint64_t packets_ = 0;
  std::uint64_t skipped_ = 0;
  bool failed_ = false;
  RecordError error_;
  std::vector<RecordError> skippedErrors_;
  std::vector<std::uint8_t> body_;
};

// Opens a capture file of either format, chosen by its magic number: a classic pcap
// Reader or a PcapngReader, already open. nullptr with `error` set when it is neither (the
// message says what the file looks like) or its header is bad.
std::unique_ptr<CaptureReader> openCapture(io::ByteSource& source, bool skipBad, RecordError& error);

}  // namespace skyig::protocol::pcap
