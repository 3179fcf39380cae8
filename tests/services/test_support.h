#pragma once
// Shared by the services tests: a per-test scratch directory, free loopback ports, state dumps.
#include "services/udp_socket.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace skyig::services::testing {

// A directory of its own under the temporary directory for the running test, emptied first.
inline std::filesystem::path freshTestDirectory(const std::string& prefix) {
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name());
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

}  // namespace skyig::services::testing
