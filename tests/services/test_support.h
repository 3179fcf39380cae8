#pragma once
// Shared by the services tests: a per-test scratch directory, free loopback ports, state dumps.
#include "services/udp_socket.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <thread>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

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

// Waits until `frames` has advanced by `count` from its value now: the node has rendered (and
// dumped) what it had received before the call.
inline bool waitForFrames(const std::atomic<std::uint64_t>& frames, std::uint64_t count) {
  const std::uint64_t start = frames.load();
  return waitUntil([&] { return frames.load() >= start + count; });
}

}  // namespace skyig::services::testing
