#pragma once
// Test helper: a path in the test temp directory unique to this process, so tests running
// in parallel (ctest -j, other worktrees on the same machine) never share a file.
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

namespace skyig::protocol::test {

inline std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "skyig_" + std::to_string(::getpid()) + "_" + name;
}

}  // namespace skyig::protocol::test
