#include "protocol/pcap/udp_frame.h"

#include "protocol/byte_order.h"

namespace skyig::protocol::pcap {

namespace {

constexpr std::size_t kEthernetHeader = 14;
constexpr std::size_t kIpv4Header = 20;
constexpr std::size_t kUdpHeader = 8;
constexpr std::uint16_t kEtherTypeIpv4 = 0x0800;
constexpr std::uint16_t kEtherTypeVlan = 0x8100;
constexpr std::uint16_t kEtherTypeQinQ = 0x88A8;

// One's-complement sum of 16-bit big-endian words (RFC 1071).
std::uint32_t sum16(std::span<const std::uint8_t> b, std::uint32_t acc = 0) {
  std::size_t i = 0;
  for (; i + 1 < b.size(); i += 2) acc += static_cast<std::uint32_t>(b[i] << 8 | b[i + 1]);
  if (i < b.size()) acc += static_cast<std::uint32_t>(b[i] << 8);
  return acc;
}

std::uint16_t fold(std::uint32_t acc) {
  while ((acc >> 16) != 0) acc = (acc & 0xFFFFu) + (acc >> 16);
  return static_cast<std::uint16_t>(~acc & 0xFFFFu);
}

FrameError parseIpv4(std::span<const std::uint8_t> ip, UdpDatagram& out) {
  if (ip.size() < kIpv4Header) return FrameError::truncated;
  if ((ip[0] >> 4) != 4) return FrameError::notIpv4;
  const std::size_t ihl = static_cast<std::size_t>(ip[0] & 0x0F) * 4;
  const std::size_t total = loadU16(&ip[2], ByteOrder::big);
  if (ihl < kIpv4Header || total < ihl) return FrameError::badIpHeader;
  if (total > ip.size()) return FrameError::truncated;
  const std::uint16_t fragment = loadU16(&ip[6], ByteOrder::big);
  if ((fragment & 0x3FFFu) != 0) return FrameError::fragmented;  // MF flag or an offset
  if (ip[9] != 17) return FrameError::notUdp;
  const auto udp = ip.subspan(ihl, total - ihl);  // Ethernet padding after `total` is ignored
  if (udp.size() < kUdpHeader) return FrameError::truncated;
  const std::size_t udpLength = loadU16(&udp[4], ByteOrder::big);
  if (udpLength < kUdpHeader || udpLength > udp.size()) return FrameError::badUdpLength;
  out.source.ip = {ip[12], ip[13], ip[14], ip[15]};
  out.destination.ip = {ip[16], ip[17], ip[18], ip[19]};
  out.source.port = loadU16(&udp[0], ByteOrder::big);
  out.destination.port = loadU16(&udp[2], ByteOrder::big);
  out.payload = udp.subspan(kUdpHeader, udpLength - kUdpHeader);
  return FrameError::none;
}

}  // namespace

const char* linkTypeName(std::uint32_t linkType) {
  switch (linkType) {
    case kLinkNull: return "NULL (BSD loopback)";
    case kLinkEthernet: return "ETHERNET";
    case kLinkRaw: return "RAW";
    case kLinkLinuxSll: return "LINUX_SLL";
    case kLinkIpv4: return "IPV4";
    case kLinkLinuxSll2: return "LINUX_SLL2";
    default: return "unsupported";
  }
}

std::string toString(const Endpoint& e) {
  return std::to_string(e.ip[0]) + "." + std::to_string(e.ip[1]) + "." + std::to_string(e.ip[2]) + "." +
         std::to_string(e.ip[3]) + ":" + std::to_string(e.port);
}

const char* toString(FrameError e) {
  switch (e) {
    case FrameError::none: return "no error";
    case FrameError::unsupportedLinkType: return "unsupported link type";
    case FrameError::truncated: return "frame ends inside a header";
    case FrameError::notIpv4: return "not IPv4";
    case FrameError::badIpHeader: return "bad IPv4 header";
    case FrameError::fragmented: return "IPv4 fragment (not reassembled)";
    case FrameError::notUdp: return "not UDP";
    case FrameError::badUdpLength: return "bad UDP length";
  }
  return "unknown error";
}

FrameError parseUdpFrame(std::uint32_t linkType, std::span<const std::uint8_t> frame, UdpDatagram& out) {
  switch (linkType) {
    case kLinkEthernet: {
      if (frame.size() < kEthernetHeader) return FrameError::truncated;
      std::size_t off = 12;
      std::uint16_t type = loadU16(&frame[off], ByteOrder::big);
      while (type == kEtherTypeVlan || type == kEtherTypeQinQ) {  // skip 802.1Q / 802.1ad tags
        off += 4;
        if (frame.size() < off + 2) return FrameError::truncated;
        type = loadU16(&frame[off], ByteOrder::big);
      }
      if (type != kEtherTypeIpv4) return FrameError::notIpv4;
      return parseIpv4(frame.subspan(off + 2), out);
    }
    case kLinkRaw:
    case kLinkIpv4: return parseIpv4(frame, out);
    case kLinkNull: {
      if (frame.size() < 4) return FrameError::truncated;
      // AF_INET is 2 on every BSD and Linux; the word is in the capturing host's order.
      const bool inet = loadU32(frame.data(), ByteOrder::little) == 2 || loadU32(frame.data(), ByteOrder::big) == 2;
      if (!inet) return FrameError::notIpv4;
      return parseIpv4(frame.subspan(4), out);
    }
    case kLinkLinuxSll: {
      if (frame.size() < 16) return FrameError::truncated;
      if (loadU16(&frame[14], ByteOrder::big) != kEtherTypeIpv4) return FrameError::notIpv4;
      return parseIpv4(frame.subspan(16), out);
    }
    case kLinkLinuxSll2: {
      if (frame.size() < 20) return FrameError::truncated;
      if (loadU16(&frame[0], ByteOrder::big) != kEtherTypeIpv4) return FrameError::notIpv4;
      return parseIpv4(frame.subspan(20), out);
    }
    default: return FrameError::unsupportedLinkType;
  }
}

std::string buildUdpFrame(std::uint32_t linkType, const Endpoint& source, const Endpoint& destination,
                          std::span<const std::uint8_t> payload, std::uint16_t ipId, std::vector<std::uint8_t>& out) {
  out.clear();
  constexpr std::size_t kMaxPayload = 65535 - kIpv4Header - kUdpHeader;
  if (payload.size() > kMaxPayload)
    return "UDP payload of " + std::to_string(payload.size()) + " bytes exceeds " + std::to_string(kMaxPayload);
  std::size_t link = 0;
  if (linkType == kLinkEthernet)
    link = kEthernetHeader;
  else if (linkType != kLinkRaw && linkType != kLinkIpv4)
    return std::string("cannot write link type ") + std::to_string(linkType) + " (" + linkTypeName(linkType) +
           "): use ETHERNET (1), RAW (101) or IPV4 (228)";
  const std::size_t ipTotal = kIpv4Header + kUdpHeader + payload.size();
  out.assign(link + ipTotal, 0);
  std::uint8_t* p = out.data();
  if (link != 0) {
    // Locally administered unicast MACs (02:...): the capture records no real hardware.
    const std::uint8_t dstMac[6] = {0x02, 0x00, 0x00, 0x00, 0x00, 0x02};
    const std::uint8_t srcMac[6] = {0x02, 0x00, 0x00, 0x00, 0x00, 0x01};
    for (int i = 0; i < 6; ++i) {
      p[i] = dstMac[i];
      p[6 + i] = srcMac[i];
    }
    storeU16(p + 12, kEtherTypeIpv4, ByteOrder::big);
  }
  std::uint8_t* ip = p + link;
  ip[0] = 0x45;  // version 4, IHL 5 words
  storeU16(ip + 2, static_cast<std::uint16_t>(ipTotal), ByteOrder::big);
  storeU16(ip + 4, ipId, ByteOrder::big);
  storeU16(ip + 6, 0x4000, ByteOrder::big);  // don't fragment
  ip[8] = 64;                                // TTL
  ip[9] = 17;                                // UDP
  for (int i = 0; i < 4; ++i) {
    ip[12 + i] = source.ip[static_cast<std::size_t>(i)];
    ip[16 + i] = destination.ip[static_cast<std::size_t>(i)];
  }
  storeU16(ip + 10, fold(sum16({ip, kIpv4Header})), ByteOrder::big);
  std::uint8_t* udp = ip + kIpv4Header;
  const auto udpLength = static_cast<std::uint16_t>(kUdpHeader + payload.size());
  storeU16(udp + 0, source.port, ByteOrder::big);
  storeU16(udp + 2, destination.port, ByteOrder::big);
  storeU16(udp + 4, udpLength, ByteOrder::big);
  for (std::size_t i = 0; i < payload.size(); ++i) udp[kUdpHeader + i] = payload[i];
  // UDP checksum over the pseudo-header (source, destination, protocol, length) and the
  // datagram (RFC 768); a computed 0 is sent as 0xFFFF.
  std::uint32_t acc = sum16({ip + 12, 8});
  acc += 17u + udpLength;
  acc = sum16({udp, udpLength}, acc);
  std::uint16_t checksum = fold(acc);
  if (checksum == 0) checksum = 0xFFFF;
  storeU16(udp + 6, checksum, ByteOrder::big);
  return {};
}

}  // namespace skyig::protocol::pcap
