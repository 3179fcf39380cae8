#pragma once
// CIGI 3.3 encoder: typed packets to bytes, in either byte order. Used by the IG for Start
// of Frame and by the host emulator and the tests for host-to-IG messages.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "protocol/byte_order.h"
#include "protocol/cigi/packets.h"

namespace skyig::protocol::cigi {

// Largest CIGI message skyig writes: one UDP datagram over IPv4 (65535 - 20 - 8).
inline constexpr std::size_t kMaxMessageSize = 65507;

// Appends one packet to `out` in byte order `order`. Returns an empty string on success, or
// a message naming the field whose value does not fit its bit field (then nothing is
// appended), e.g. "Weather Control: Cloud Type = 20 does not fit in 4 bits".
std::string appendPacket(std::vector<std::uint8_t>& out, const Packet& packet, ByteOrder order);

// Encodes a whole message (one datagram) into `out` (replacing its content). The first
// packet must be IG Control (host to IG) or Start of Frame (IG to host): they carry the
// version and the byte-swap magic by which the receiver tells the byte order. Returns an
// empty string on success, or what is wrong.
std::string encodeMessage(std::span<const Packet> packets, ByteOrder order, std::vector<std::uint8_t>& out);

// CIGI 4.0 (the subset in protocol/cigi/layouts4.h): IG Control, Entity Control (sent as
// Entity Position Control: the pose only), Celestial Sphere Control (with seconds),
// Atmosphere Control, View Control, View Definition, Sensor Control and Start of Frame. Other types are
// refused by name.
std::string appendPacket4(std::vector<std::uint8_t>& out, const Packet& packet, ByteOrder order);
std::string encodeMessage4(std::span<const Packet> packets, ByteOrder order, std::vector<std::uint8_t>& out);

}  // namespace skyig::protocol::cigi
