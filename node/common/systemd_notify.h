#pragma once
// systemd's service notification protocol, without libsystemd: a service started with
// Type=notify tells the service manager it is ready ("READY=1") and, with WatchdogSec=, that it
// is alive ("WATCHDOG=1"), each a datagram of newline-separated KEY=VALUE lines sent to the
// AF_UNIX datagram socket named by $NOTIFY_SOCKET (sd_notify(3); systemd.service(5), Type=notify
// and WatchdogSec=). A name that starts with '@' is in Linux's abstract namespace (unix(7)): the
// '@' stands for the leading NUL byte. $WATCHDOG_USEC is the watchdog interval; when
// $WATCHDOG_PID is set and names another process, the watchdog is not this process's.
// Outside systemd (no $NOTIFY_SOCKET) every call does nothing.
#include <chrono>
#include <string>
#include <string_view>

namespace skyig::services {

class SystemdNotifier {
 public:
  // Inactive: sends nothing.
  SystemdNotifier() = default;
  // Sends to `socketName` (a path, or '@' + an abstract name); pets the watchdog every half of
  // `watchdogInterval` (zero: no watchdog). A name that is neither is logged and ignored.
  SystemdNotifier(const std::string& socketName, std::chrono::microseconds watchdogInterval);
  ~SystemdNotifier();
  SystemdNotifier(const SystemdNotifier&) = delete;
  SystemdNotifier& operator=(const SystemdNotifier&) = delete;

  // From $NOTIFY_SOCKET, $WATCHDOG_USEC and $WATCHDOG_PID, as systemd sets them.
  static SystemdNotifier fromEnvironment();

  bool active() const { return fd_ >= 0; }
  std::chrono::microseconds watchdogInterval() const { return watchdogInterval_; }

  // Sends `state` ("READY=1", "STOPPING=1", ...) without blocking. False when inactive or the
  // send failed (a full queue included); a failure is logged once, never thrown: the node
  // renders on whatever systemd thinks.
  bool notify(std::string_view state);

  // The render loop calls this after every frame: the first sends READY=1 (the node is ready
  // when it has drawn, not when it has started), later ones WATCHDOG=1 whenever half the
  // watchdog interval has passed since the last (sd_watchdog_enabled(3) recommends half), so a
  // hung render loop is restarted by systemd while a slow one is not.
  void frameDone(std::chrono::steady_clock::time_point now);

 private:
  int fd_ = -1;
  std::string address_;  // sockaddr_un's sun_path bytes, the abstract name's NUL included
  std::chrono::microseconds watchdogInterval_{0};
  bool ready_ = false;
  bool failureLogged_ = false;
  std::chrono::steady_clock::time_point lastPet_{};
};

}  // namespace skyig::services
