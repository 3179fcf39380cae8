#pragma once
// A UDP socket for CIGI: bound to an address and port, optionally joined to a multicast group.
#include "node/host/sender.h"

#include <netinet/in.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace skyig::services {

class NetworkError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Endpoint {
  std::string address = "0.0.0.0";
  std::uint16_t port = 0;
  std::string toString() const { return address + ":" + std::to_string(port); }
};

// "ADDR:PORT", ADDR an IPv4 address or a host name resolved (getaddrinfo) to its first IPv4
// address; throws NetworkError naming the text (and the name that did not resolve).
Endpoint parseEndpoint(const std::string& text);
// Whether `address` is a dotted IPv4 address.
bool isIpv4Address(const std::string& address);
// Whether `address` is an IPv4 multicast group (224.0.0.0/4).
bool isMulticastGroup(const std::string& address);
sockaddr_in toSockaddr(const Endpoint& e);
Endpoint fromSockaddr(const sockaddr_in& a);
// The kernel's address and the host modules' (node/host/sender.h), both ways.
sockaddr_in toSockaddr(const Sender& s);
Sender toSender(const sockaddr_in& a);

class UdpSocket {
 public:
  // Binds to `local` (port 0: any free port); joins `multicastGroup` when given, on the
  // interface with address `multicastInterface` (default: the bind address; for 0.0.0.0 the
  // kernel's choice by route). A node that receives a group binds 0.0.0.0 (a socket bound to
  // one unicast address does not receive the group's datagrams) and names the interface here.
  explicit UdpSocket(const Endpoint& local, const std::optional<std::string>& multicastGroup = std::nullopt,
                     const std::optional<std::string>& multicastInterface = std::nullopt);
  ~UdpSocket();
  UdpSocket(const UdpSocket&) = delete;
  UdpSocket& operator=(const UdpSocket&) = delete;

  // Waits up to `timeout` for a datagram; returns its size (0 after a timeout or an
  // interruption) and the sender. Datagrams larger than the buffer are truncated (and
  // then reported by the decoder as malformed).
  std::size_t receive(std::span<std::uint8_t> buffer, sockaddr_in& from, std::chrono::milliseconds timeout);
  bool sendTo(std::span<const std::uint8_t> bytes, const sockaddr_in& to);
  // Multicast sent from this socket leaves through the interface with address `interfaceAddress`
  // (IP_MULTICAST_IF) with time-to-live `ttl` (0: never leaves the machine; 1: the local
  // network), and is looped back to this machine's members (IP_MULTICAST_LOOP), so nodes on the
  // host's machine hear it. Throws NetworkError naming what the kernel refused.
  void sendMulticastThrough(const std::string& interfaceAddress, int ttl);
  Endpoint localEndpoint() const;

 private:
  int fd_ = -1;
};

}  // namespace skyig::services
