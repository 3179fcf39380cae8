#include "node/common/systemd_notify.h"

#include <spdlog/spdlog.h>

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstddef>
#include <cstdlib>
#include <cstring>

namespace skyig::services {

SystemdNotifier::SystemdNotifier(const std::string& socketName, std::chrono::microseconds watchdogInterval)
    : watchdogInterval_(watchdogInterval) {
  sockaddr_un probe{};
  if (socketName.size() < 2 || (socketName[0] != '/' && socketName[0] != '@') ||
      socketName.size() > sizeof(probe.sun_path)) {
    spdlog::warn("NOTIFY_SOCKET=\"{}\" is not a socket path or an @abstract name: systemd is not notified", socketName);
    return;
  }
  address_ = socketName;
  if (address_[0] == '@') address_[0] = '\0';
  fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) spdlog::warn("NOTIFY_SOCKET: cannot create a unix datagram socket: {}", std::strerror(errno));
}

SystemdNotifier::~SystemdNotifier() {
  if (fd_ >= 0) ::close(fd_);
}

SystemdNotifier SystemdNotifier::fromEnvironment() {
  const char* socketName = std::getenv("NOTIFY_SOCKET");
  if (!socketName || !*socketName) return {};
  std::chrono::microseconds interval{0};
  const char* usec = std::getenv("WATCHDOG_USEC");
  const char* pid = std::getenv("WATCHDOG_PID");
  const bool ours = !pid || !*pid || std::strtoll(pid, nullptr, 10) == static_cast<long long>(::getpid());
  if (usec && *usec && ours) interval = std::chrono::microseconds(std::strtoll(usec, nullptr, 10));
  if (interval.count() < 0) interval = std::chrono::microseconds(0);
  return SystemdNotifier(socketName, interval);
}

bool SystemdNotifier::notify(std::string_view state) {
  if (fd_ < 0) return false;
  sockaddr_un to{};
  to.sun_family = AF_UNIX;
  std::memcpy(to.sun_path, address_.data(), address_.size());
  // An abstract name's length is exactly its bytes (no terminating NUL); a path may have one.
  const auto length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + address_.size());
  // Never blocks the render loop: a unix datagram socket whose reader lags (its queue holds a
  // few datagrams) would block a plain send until the reader drains it; then the notification
  // is dropped (EAGAIN) and the next one tries again.
  if (::sendto(fd_, state.data(), state.size(), MSG_NOSIGNAL | MSG_DONTWAIT, reinterpret_cast<const sockaddr*>(&to),
               length) == static_cast<ssize_t>(state.size()))
    return true;
  if (!failureLogged_) {
    spdlog::warn("NOTIFY_SOCKET: cannot send \"{}\": {}", state, std::strerror(errno));
    failureLogged_ = true;
  }
  return false;
}

void SystemdNotifier::frameDone(std::chrono::steady_clock::time_point now) {
  if (fd_ < 0) return;
  if (!ready_) {
    ready_ = true;
    lastPet_ = now;
    notify("READY=1");
    return;
  }
  if (watchdogInterval_.count() > 0 && now - lastPet_ >= watchdogInterval_ / 2) {
    lastPet_ = now;
    notify("WATCHDOG=1");
  }
}

}  // namespace skyig::services
