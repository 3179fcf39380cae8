#pragma once
// CIGI 3.3 decoder: one message (one UDP datagram) in, typed packets out. It also reads
// the CIGI 4.0 subset of protocol/cigi/layouts4.h into the same structs (majorVersion 4).
//
// - The byte order comes from the byte-swap magic (0x8000 in the sender's order) at offset 6
//   of the first packet, which must be IG Control (host to IG) or Start of Frame (IG to
//   host); it applies to every packet of the message.
// - Known packets must have exactly their ICD size; packets skyig does not decode (other
//   ids, user-defined 201-255) are skipped by their size byte and counted.
// - At the first malformed packet decoding stops: the packets before it are kept and the
//   error says what was wrong, where (byte offset) and which packet.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/byte_order.h"
#include "protocol/cigi/packets.h"

namespace skyig::protocol::cigi {

// What can be wrong with a message. Stable values: they index error counters.
enum class ErrorKind : std::uint8_t {
  emptyMessage = 0,      // zero bytes
  truncatedHeader,       // fewer than 2 bytes left where a packet header should be
  missingFirstPacket,    // the first packet is neither IG Control nor Start of Frame
  unsupportedVersion,    // CIGI 1, 2, 3.0/3.1, or an unknown major/minor version
  badByteSwapMagic,      // offset 6 of the first packet is neither 80 00 nor 00 80
  packetSizeTooSmall,    // size byte 0 or 1: the packet cannot even hold its header
  packetPastEnd,         // size byte runs past the end of the datagram (truncated message)
  wrongPacketSize,       // a known packet whose size byte differs from its ICD size
};
inline constexpr std::size_t kErrorKindCount = 8;

const char* toString(ErrorKind k);

struct DecodeError {
  ErrorKind kind = ErrorKind::emptyMessage;
  std::size_t offset = 0;        // byte offset of the offending packet (or field) in the message
  std::uint16_t packetId = 0;    // id of the offending packet, when there is one
  bool cigi4 = false;            // the message is CIGI 4 (16-bit ids)
  std::size_t packetSize = 0;    // its size byte (or the bytes available)
  std::uint32_t value = 0;       // the offending value (version, magic, expected size)
  std::string describe() const;  // one line naming kind, offset, packet and values
};

struct DecodedMessage {
  ByteOrder byteOrder = ByteOrder::big;
  std::uint8_t majorVersion = 0;     // 3, or 4 for a CIGI 4.0 message
  std::uint8_t minorVersion = 0;
  std::vector<Packet> packets;       // well-formed packets, in message order
  std::size_t skippedPackets = 0;    // packets of ids skyig does not decode
  std::optional<DecodeError> error;  // set when the message was malformed
  bool ok() const { return !error.has_value(); }
};

// Decodes into `out`, reusing its storage (no allocation once warm).
void decodeMessage(std::span<const std::uint8_t> bytes, DecodedMessage& out);
DecodedMessage decodeMessage(std::span<const std::uint8_t> bytes);

}  // namespace skyig::protocol::cigi
