// skyig under systemd: the notification protocol (sd_notify(3)) spoken to a real unix datagram
// socket the test binds, by the notifier and by a `serve` process, and the table cache in the
// directory systemd makes for the unit.
#include "node/config/node_tables.h"
#include "node/common/systemd_notify.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using skyig::services::SystemdNotifier;

namespace {

// The service manager's end: a unix datagram socket bound to a path, or to an abstract name
// when `name` starts with '@'.
class NotifySocket {
 public:
  explicit NotifySocket(const std::string& name) {
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    EXPECT_GE(fd_, 0) << std::strerror(errno);
    sockaddr_un a{};
    a.sun_family = AF_UNIX;
    std::memcpy(a.sun_path, name.data(), name.size());
    if (name[0] == '@') a.sun_path[0] = '\0';
    const auto length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + name.size());
    EXPECT_EQ(::bind(fd_, reinterpret_cast<const sockaddr*>(&a), length), 0) << name << ": " << std::strerror(errno);
  }
  ~NotifySocket() { ::close(fd_); }

  // The next datagram, or nothing within `timeout`.
  std::optional<std::string> receive(std::chrono::milliseconds timeout) {
    timeval tv{static_cast<time_t>(timeout.count() / 1000), static_cast<suseconds_t>(timeout.count() % 1000 * 1000)};
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    char buffer[4096];
    const ssize_t n = ::recv(fd_, buffer, sizeof buffer, 0);
    if (n < 0) return std::nullopt;
    return std::string(buffer, static_cast<size_t>(n));
  }

 private:
  int fd_ = -1;
};

TEST(SystemdNotify, SendsReadyAfterTheFirstFrameThenPetsTheWatchdogEveryHalfInterval) {
  const fs::path dir = skyig::services::testing::freshTestDirectory("skyig_notify_");
  NotifySocket manager((dir / "notify").string());
  SystemdNotifier notifier((dir / "notify").string(), 100ms);
  ASSERT_TRUE(notifier.active());
  const auto t0 = std::chrono::steady_clock::now();
  notifier.frameDone(t0);
  EXPECT_EQ(manager.receive(2000ms), "READY=1");
  notifier.frameDone(t0 + 49ms);  // less than half the interval since READY: nothing
  EXPECT_EQ(manager.receive(50ms), std::nullopt);
  notifier.frameDone(t0 + 50ms);
  EXPECT_EQ(manager.receive(2000ms), "WATCHDOG=1");
  notifier.frameDone(t0 + 60ms);
  EXPECT_EQ(manager.receive(50ms), std::nullopt);
  notifier.frameDone(t0 + 100ms);
  EXPECT_EQ(manager.receive(2000ms), "WATCHDOG=1");
  fs::remove_all(dir);
}

TEST(SystemdNotify, ReachesAnAbstractSocketNamedWithAnAt) {
  const std::string name = "@skyig-notify-test-" + std::to_string(::getpid());
  NotifySocket manager(name);
  SystemdNotifier notifier(name, 0ms);
  ASSERT_TRUE(notifier.active());
  notifier.frameDone(std::chrono::steady_clock::now());
  EXPECT_EQ(manager.receive(2000ms), "READY=1");
  notifier.frameDone(std::chrono::steady_clock::now() + 1h);  // no watchdog configured: READY only
  EXPECT_EQ(manager.receive(50ms), std::nullopt);
}

TEST(SystemdNotify, IsSilentWithoutNotifySocketAndRefusesARelativeName) {
  ::unsetenv("NOTIFY_SOCKET");
  EXPECT_FALSE(SystemdNotifier::fromEnvironment().active());
  SystemdNotifier relative("notify", 0ms);
  EXPECT_FALSE(relative.active());
  EXPECT_FALSE(relative.notify("READY=1"));
}

TEST(SystemdNotify, WatchdogOfAnotherProcessIsNotPetted) {
  const fs::path dir = skyig::services::testing::freshTestDirectory("skyig_notify_");
  ::setenv("NOTIFY_SOCKET", (dir / "notify").c_str(), 1);
  ::setenv("WATCHDOG_USEC", "30000000", 1);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid()).c_str(), 1);
  EXPECT_EQ(SystemdNotifier::fromEnvironment().watchdogInterval(), 30s);
  ::setenv("WATCHDOG_PID", std::to_string(::getpid() + 1).c_str(), 1);
  EXPECT_EQ(SystemdNotifier::fromEnvironment().watchdogInterval(), 0s);
  for (const char* v : {"NOTIFY_SOCKET", "WATCHDOG_USEC", "WATCHDOG_PID"}) ::unsetenv(v);
  fs::remove_all(dir);
}

// `skyig serve` as systemd runs it: READY=1 comes once frame 0 is drawn (its state-dump line is
// already written), then WATCHDOG=1 from the render loop. The test reads two datagrams of the
// forty frames' worth: the node must not block on the full socket queue, and exits.
TEST(SystemdNotify, ServeSendsReadyAfterItsFirstFrameThenWatchdogAndNeverBlocksOnIt) {
  const fs::path dir = skyig::services::testing::freshTestDirectory("skyig_notify_");
  NotifySocket manager((dir / "notify").string());
  std::ofstream(dir / "analytic.toml")
      << "[sky]\nmodel = \"preetham\"\n[[channel]]\nname = \"front\"\nwidth = 64\nheight = 48\n";
  const std::string config = (dir / "analytic.toml").string(), states = (dir / "states.jsonl").string(),
                    log = (dir / "stderr.txt").string(), socketPath = (dir / "notify").string();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::setenv("NOTIFY_SOCKET", socketPath.c_str(), 1);
    ::setenv("WATCHDOG_USEC", "40000", 1);  // a pet every 20 ms: every frame at 60 Hz
    if (!std::freopen(log.c_str(), "w", stderr)) ::_exit(126);
    ::execl(SKYIG_EXECUTABLE, SKYIG_EXECUTABLE, "serve", "--config", config.c_str(), "--headless", "--frames", "40",
            "--frame-rate", "60", "--listen", "127.0.0.1:0", "--dump-state", states.c_str(),
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto ready = manager.receive(60000ms);
  // When READY=1 arrives, frame 0 has been drawn and dumped.
  const size_t framesAtReady = skyig::services::testing::readStateDump(states).size();
  const auto pet = manager.receive(20000ms);
  int status = 0;
  const bool exited = skyig::services::testing::waitUntil([&] { return ::waitpid(child, &status, WNOHANG) == child; },
                                                          std::chrono::milliseconds(120000));
  if (!exited) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
  }
  ASSERT_TRUE(exited) << "serve did not finish its 40 frames (blocked on the notify socket?)";
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "serve failed; see " << log;
  EXPECT_EQ(ready, "READY=1");
  EXPECT_GE(framesAtReady, 1u);
  EXPECT_EQ(pet, "WATCHDOG=1");
  fs::remove_all(dir);
}

TEST(SystemdNotify, TablesAreCachedInTheServicesCacheDirectory) {
  skyig::services::AtmosphereSettings settings;
  ::setenv("CACHE_DIRECTORY", "/var/cache/skyig:/var/cache/other", 1);
  EXPECT_EQ(skyig::services::cacheDirectory(settings), fs::path("/var/cache/skyig"));
  settings.cacheDir = "/srv/tables";  // the configuration's atmosphere_cache wins
  EXPECT_EQ(skyig::services::cacheDirectory(settings), fs::path("/srv/tables"));
  ::unsetenv("CACHE_DIRECTORY");
  ::setenv("XDG_CACHE_HOME", "/home/x/.cache", 1);
  settings.cacheDir.clear();
  EXPECT_EQ(skyig::services::cacheDirectory(settings), fs::path("/home/x/.cache/skyig"));
  ::unsetenv("XDG_CACHE_HOME");
}

}  // namespace
