#pragma once
// Shared by the services tests: a per-test scratch directory, a skyig command run to its end,
// free loopback ports, state dumps.
#include "node/transport/udp_socket.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdlib>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <thread>
#include <fstream>
#include <string>
#include <vector>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <sstream>

extern char** environ;

namespace skyig::services::testing {

// A directory of its own under the temporary directory for the running test, emptied first.
inline std::filesystem::path freshTestDirectory(const std::string& prefix) {
  // The process id keeps two checkouts' test runs on one machine out of each other's folders.
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" +
                    std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A file's bytes.
inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// What a `skyig` command that ran to its end said, and its exit code (-1: killed).
struct SkyigResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// Runs `skyig ARGS` (SKYIG_EXECUTABLE) to its end, its stdout and stderr through files in `dir`
// (the test's own), with `environment` given to env(1) first (e.g. "-u SKYIG_DATA_DIR",
// "LP_NUM_THREADS=2"). The physical sky's tables come from the build tree's cache, which the
// atmosphere tests share, never from $HOME.
inline SkyigResult runSkyig(const std::string& args, const std::filesystem::path& dir,
                            const std::string& environment = "") {
  const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
  const std::string command = "env " + environment + " XDG_CACHE_HOME=" + std::string(SKYIG_BINARY_DIR) +
                              "/atmosphere-test-cache " + std::string(SKYIG_EXECUTABLE) + " " + args + " >" +
                              out.string() + " 2>" + err.string();
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(out), slurp(err)};
}

// A UDP port on loopback that was free a moment ago.
inline std::uint16_t freeLoopbackPort() {
  UdpSocket s({"127.0.0.1", 0});
  return s.localEndpoint().port;
}

// The lines of a --dump-state file.
inline std::vector<nlohmann::json> readStateDump(const std::filesystem::path& p) {
  std::vector<nlohmann::json> lines;
  std::ifstream in(p);
  std::string line;
  while (std::getline(in, line)) lines.push_back(nlohmann::json::parse(line));
  return lines;
}

// Polls `done` every 5 ms until it holds or `limit` passes; says whether it held. A node under
// test starts and drains its queues at the speed of a loaded 2-core CI machine: a fixed sleep is
// too short there and wasted time here.
inline bool waitUntil(const std::function<bool()>& done,
                      std::chrono::milliseconds limit = std::chrono::milliseconds(20000)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

// How long a node under test may take to its first frame: before it the node compiles the
// programs of its day's lights and weathers (render/warm_up_states.h), seconds on llvmpipe and
// a minute or more with two sanitized nodes sharing a loaded 2-core CI machine.
inline constexpr std::chrono::milliseconds kFirstFrameLimit{240000};

// Waits for a node's first frame (its socket is bound, its programs compiled).
inline bool waitForFirstFrame(const std::atomic<std::uint64_t>& frames) {
  return waitUntil([&] { return frames.load() > 0; }, kFirstFrameLimit);
}

// A thread that runs a node until `stop` is set: stopped and joined however the test leaves its
// scope, so a failed ASSERT that returns early ends the test, not the whole program (a joinable
// std::thread destroyed calls std::terminate).
class StoppedThread {
 public:
  StoppedThread(std::atomic<bool>& stop, std::function<void()> body) : stop_(stop), thread_(std::move(body)) {}
  ~StoppedThread() { join(); }
  StoppedThread(const StoppedThread&) = delete;
  StoppedThread& operator=(const StoppedThread&) = delete;
  void join() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::atomic<bool>& stop_;
  std::thread thread_;
};

// Waits until `frames` has advanced by `count` from its value now: the node has rendered (and
// dumped) what it had received before the call.
inline bool waitForFrames(const std::atomic<std::uint64_t>& frames, std::uint64_t count) {
  const std::uint64_t start = frames.load();
  return waitUntil([&] { return frames.load() >= start + count; });
}

// A `skyig` process (SKYIG_EXECUTABLE) with its stdout and stderr in `log`; stopped with
// SIGTERM when it goes out of scope.
class SkyigProcess {
 public:
  SkyigProcess(const std::string& args, const std::filesystem::path& log) : log_(log) {
    // The shell execs skyig: the id spawned is skyig's.
    const std::string command = "exec " + std::string(SKYIG_EXECUTABLE) + " " + args + " >" + log_.string() + " 2>&1";
    const char* argv[] = {"/bin/sh", "-c", command.c_str(), nullptr};
    if (posix_spawn(&pid_, "/bin/sh", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0) pid_ = -1;
  }
  ~SkyigProcess() { stop(); }
  SkyigProcess(const SkyigProcess&) = delete;
  SkyigProcess& operator=(const SkyigProcess&) = delete;
  bool running() {
    if (pid_ <= 0) return false;
    if (::waitpid(pid_, &status_, WNOHANG) != pid_) return true;
    pid_ = -1;  // exited, and reaped: never signalled again
    return false;
  }
  std::string output() const {
    std::ifstream in(log_);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
  // SIGTERM, and its exit code (-1 when it did not exit normally).
  int stop() {
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, &status_, 0);
      pid_ = -1;
    }
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : -1;
  }
  // Waits for the process to exit by itself; its exit code (-1 when it did not exit normally).
  int wait() {
    if (pid_ > 0) {
      ::waitpid(pid_, &status_, 0);
      pid_ = -1;
    }
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : -1;
  }

 private:
  pid_t pid_ = -1;
  int status_ = -1;
  std::filesystem::path log_;
};

}  // namespace skyig::services::testing
