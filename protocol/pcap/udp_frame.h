#pragma once
// The link, IPv4 and UDP headers around a CIGI datagram in a capture: built for the pcap
// writer (so Wireshark's CIGI dissector and tcpdump see ordinary UDP), parsed for replay.
// RFC 791 (IPv4), RFC 768 (UDP), IEEE 802.3 Ethernet II, and the tcpdump.org link-type list.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace skyig::protocol::pcap {

// Link-layer header types (https://www.tcpdump.org/linktypes.html).
enum LinkType : std::uint32_t {
  kLinkNull = 0,         // BSD loopback: 4-byte address family in the capturing host's order
  kLinkEthernet = 1,     // Ethernet II (802.1Q VLAN tags skipped on read)
  kLinkRaw = 101,        // raw IP, version from the first nibble
  kLinkLinuxSll = 113,   // Linux "cooked" capture v1 (tcpdump -i any, older)
  kLinkIpv4 = 228,       // raw IPv4
  kLinkLinuxSll2 = 276,  // Linux "cooked" capture v2 (tcpdump -i any)
};
const char* linkTypeName(std::uint32_t linkType);

struct Endpoint {
  std::array<std::uint8_t, 4> ip{127, 0, 0, 1};
  std::uint16_t port = 0;
  bool operator==(const Endpoint&) const = default;
};
std::string toString(const Endpoint& e);  // "10.0.0.1:8004"

struct UdpDatagram {
  Endpoint source;
  Endpoint destination;
  std::span<const std::uint8_t> payload;  // points into the frame given to parseUdpFrame
};

enum class FrameError : std::uint8_t {
  none = 0,
  unsupportedLinkType,
  truncated,         // the frame ends inside a header
  notIpv4,           // another ethertype / IP version
  badIpHeader,       // IHL < 5 or total length inconsistent
  fragmented,        // an IP fragment: skyig does not reassemble
  notUdp,            // another IP protocol
  badUdpLength,      // UDP length field disagrees with the IP payload
};
inline constexpr std::size_t kFrameErrorCount = 8;
const char* toString(FrameError e);

// Finds the UDP datagram in a captured frame of the given link type.
FrameError parseUdpFrame(std::uint32_t linkType, std::span<const std::uint8_t> frame, UdpDatagram& out);

// Builds a frame (link header + IPv4 + UDP with checksums) carrying `payload`; link type
// Ethernet, Raw or IPv4. `ipId` is the IPv4 identification field. Returns an empty string
// or what is wrong (payload too large, unsupported link type).
std::string buildUdpFrame(std::uint32_t linkType, const Endpoint& source, const Endpoint& destination,
                          std::span<const std::uint8_t> payload, std::uint16_t ipId,
                          std::vector<std::uint8_t>& out);

}  // namespace skyig::protocol::pcap
