#include "node/transport/udp_socket.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace skyig::services {

namespace {
[[noreturn]] void fail(const std::string& what) { throw NetworkError(what + ": " + std::strerror(errno)); }
}  // namespace

Endpoint parseEndpoint(const std::string& text) {
  const size_t colon = text.rfind(':');
  if (colon == std::string::npos || colon == 0)
    throw NetworkError("\"" + text + "\" is not ADDRESS:PORT (an IPv4 address or a host name)");
  char* end = nullptr;
  const long port = std::strtol(text.c_str() + colon + 1, &end, 10);
  if (*end != '\0' || colon + 1 == text.size() || port < 0 || port > 65535)
    throw NetworkError("\"" + text + "\": port must be 0..65535");
  const std::string host = text.substr(0, colon);
  in_addr a{};
  if (inet_pton(AF_INET, host.c_str(), &a) == 1) return {host, static_cast<std::uint16_t>(port)};
  // A name ("localhost", a host in /etc/hosts or DNS): its first IPv4 address.
  addrinfo hints{};
  hints.ai_family = AF_INET;
  hints.ai_socktype = SOCK_DGRAM;
  addrinfo* found = nullptr;
  const int error = ::getaddrinfo(host.c_str(), nullptr, &hints, &found);
  if (error != 0 || !found)
    throw NetworkError("\"" + text + "\": cannot resolve \"" + host + "\" to an IPv4 address (" +
                       ::gai_strerror(error) + ")");
  const sockaddr_in resolved = *reinterpret_cast<const sockaddr_in*>(found->ai_addr);
  ::freeaddrinfo(found);
  return {fromSockaddr(resolved).address, static_cast<std::uint16_t>(port)};
}

bool isIpv4Address(const std::string& address) {
  in_addr a{};
  return inet_pton(AF_INET, address.c_str(), &a) == 1;
}

bool isMulticastGroup(const std::string& address) {
  in_addr a{};
  return inet_pton(AF_INET, address.c_str(), &a) == 1 && IN_MULTICAST(ntohl(a.s_addr));
}

sockaddr_in toSockaddr(const Endpoint& e) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(e.port);
  if (inet_pton(AF_INET, e.address.c_str(), &a.sin_addr) != 1)
    throw NetworkError("\"" + e.address + "\" is not an IPv4 address");
  return a;
}

sockaddr_in toSockaddr(const Sender& s) {
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_port = htons(s.port);
  a.sin_addr.s_addr = htonl(s.address);
  return a;
}

Sender toSender(const sockaddr_in& a) { return {ntohl(a.sin_addr.s_addr), ntohs(a.sin_port)}; }

Endpoint fromSockaddr(const sockaddr_in& a) {
  char text[INET_ADDRSTRLEN] = {};
  inet_ntop(AF_INET, &a.sin_addr, text, sizeof text);
  return {text, ntohs(a.sin_port)};
}

UdpSocket::UdpSocket(const Endpoint& local, const std::optional<std::string>& multicastGroup,
                     const std::optional<std::string>& multicastInterface) {
  fd_ = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) fail("socket(AF_INET, SOCK_DGRAM)");
  if (multicastGroup) {
    // The nodes of a dome on one machine share the group's port. A unicast port is never
    // shared: with SO_REUSEADDR a second process could bind it and silently take the stream.
    const int one = 1;
    ::setsockopt(fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  }
  const int buffer = 4 << 20;  // absorb bursts while a frame renders
  ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &buffer, sizeof buffer);
  const sockaddr_in a = toSockaddr(local);
  if (::bind(fd_, reinterpret_cast<const sockaddr*>(&a), sizeof a) != 0) {
    const int error = errno;
    ::close(fd_);
    if (error == EADDRINUSE)
      throw NetworkError("bind " + local.toString() +
                         ": the port is in use by another process (another skyig serve or record?); " +
                         "stop it or choose another --listen");
    errno = error;
    fail("bind " + local.toString());
  }
  if (multicastGroup) {
    ip_mreq m{};
    if (inet_pton(AF_INET, multicastGroup->c_str(), &m.imr_multiaddr) != 1) {
      ::close(fd_);
      throw NetworkError("\"" + *multicastGroup + "\" is not an IPv4 multicast group");
    }
    m.imr_interface = a.sin_addr;
    if (multicastInterface && inet_pton(AF_INET, multicastInterface->c_str(), &m.imr_interface) != 1) {
      ::close(fd_);
      throw NetworkError("multicast interface \"" + *multicastInterface + "\" is not an IPv4 address");
    }
    if (::setsockopt(fd_, IPPROTO_IP, IP_ADD_MEMBERSHIP, &m, sizeof m) != 0) {
      const int error = errno;
      ::close(fd_);
      errno = error;
      fail("join multicast group " + *multicastGroup + " on interface " +
           (multicastInterface ? *multicastInterface : local.address));
    }
  }
}

UdpSocket::~UdpSocket() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t UdpSocket::receive(std::span<std::uint8_t> buffer, sockaddr_in& from, std::chrono::milliseconds timeout) {
  pollfd p{fd_, POLLIN, 0};
  const int ready = ::poll(&p, 1, static_cast<int>(timeout.count()));
  if (ready <= 0) return 0;
  socklen_t length = sizeof from;
  const ssize_t n = ::recvfrom(fd_, buffer.data(), buffer.size(), MSG_TRUNC, reinterpret_cast<sockaddr*>(&from), &length);
  if (n < 0) return 0;
  return std::min(static_cast<std::size_t>(n), buffer.size());
}

bool UdpSocket::sendTo(std::span<const std::uint8_t> bytes, const sockaddr_in& to) {
  return ::sendto(fd_, bytes.data(), bytes.size(), 0, reinterpret_cast<const sockaddr*>(&to), sizeof to) ==
         static_cast<ssize_t>(bytes.size());
}

void UdpSocket::sendMulticastThrough(const std::string& interfaceAddress, int ttl) {
  in_addr interface{};
  if (inet_pton(AF_INET, interfaceAddress.c_str(), &interface) != 1)
    throw NetworkError("multicast interface \"" + interfaceAddress + "\" is not an IPv4 address");
  if (ttl < 0 || ttl > 255) throw NetworkError("multicast TTL " + std::to_string(ttl) + " is not 0..255");
  if (::setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_IF, &interface, sizeof interface) != 0)
    fail("send multicast through interface " + interfaceAddress);
  const unsigned char hops = static_cast<unsigned char>(ttl), loop = 1;
  if (::setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_TTL, &hops, sizeof hops) != 0) fail("multicast TTL " + std::to_string(ttl));
  if (::setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_LOOP, &loop, sizeof loop) != 0) fail("multicast loopback");
}

Endpoint UdpSocket::localEndpoint() const {
  sockaddr_in a{};
  socklen_t length = sizeof a;
  ::getsockname(fd_, reinterpret_cast<sockaddr*>(&a), &length);
  return fromSockaddr(a);
}

}  // namespace skyig::services
