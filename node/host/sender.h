#pragma once
// Where a host datagram came from, as the pure host modules see it: an IPv4 address and a port
// in host byte order, with no socket header, so the host state, its sessions and the public
// library that holds them never reach <netinet/in.h>. The transport (node/transport) converts
// the kernel's sockaddr_in to and from it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace skyig::services {

struct Sender {
  std::uint32_t address = 0;  // host byte order: 10.1.2.3 is 0x0A010203
  std::uint16_t port = 0;
  bool operator==(const Sender&) const = default;
  std::string toString() const;  // "10.1.2.3:40001"
};

// A dotted-decimal IPv4 address as inet_pton(AF_INET) reads it: four decimal parts 0..255, no
// leading zero (which some readers take for octal), nothing else; nullopt otherwise.
std::optional<std::uint32_t> parseIpv4(std::string_view text);
// "10.1.2.3" for 0x0A010203.
std::string ipv4ToString(std::uint32_t address);

}  // namespace skyig::services
