#pragma once
// Classic libpcap file format (https://www.tcpdump.org/manpages/pcap-savefile.5.html;
// draft-ietf-opsawg-pcap): a 24-byte file header - magic, version 2.4, thiszone, sigfigs,
// snaplen, link type - then records of a 16-byte header (seconds, micro- or nanoseconds,
// captured length, original length) and the captured bytes. All header fields are in the
// writer's byte order, told by how the magic reads.
#include <cstdint>
#include <string>

namespace skyig::protocol::pcap {

inline constexpr std::uint32_t kMagicMicro = 0xA1B2C3D4u;
inline constexpr std::uint32_t kMagicNano = 0xA1B23C4Du;
inline constexpr std::uint32_t kPcapngMagic = 0x0A0D0D0Au;  // pcapng section header block
inline constexpr std::size_t kFileHeaderSize = 24;
inline constexpr std::size_t kRecordHeaderSize = 16;
// Largest record skyig accepts whatever the snaplen says: libpcap's own limit for
// non-USB link types (MAXIMUM_SNAPLEN, 262144).
inline constexpr std::uint32_t kMaxRecordLength = 262144;

enum class Precision : std::uint8_t { micro, nano };

// Where a problem in a recording is: 1-based record number (0: the file header) and the
// byte offset of the record's header (or of the file header).
struct RecordError {
  enum class Kind : std::uint8_t {
    io,                // the file could not be read
    notPcap,           // bad magic (the message names pcapng and other known formats)
    truncatedHeader,   // the file ends inside the file header
    unsupportedVersion,
    truncatedRecordHeader,
    truncatedRecord,   // captured length runs past the end of the file
    recordTooLong,     // captured length above the snaplen and 256 KiB
    badRecordHeader,   // captured length > original length, or fraction >= 1 s
  };
  Kind kind = Kind::io;
  std::uint64_t record = 0;
  std::uint64_t offset = 0;
  std::string message;  // complete sentence naming record, offset and values
};
inline constexpr std::size_t kRecordErrorKindCount = 8;

}  // namespace skyig::protocol::pcap
