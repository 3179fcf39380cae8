// The window tests of this folder run on an X server of their program's own (tests/virtual_x.h),
// started once before the first test and stopped after the last: DISPLAY names it. Where Xvfb
// does not start, DISPLAY is left unset and the window tests fail saying so, with Xvfb's words.
#include "tests/virtual_x.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

namespace {

class OwnXDisplay : public ::testing::Environment {
 public:
  void SetUp() override {
    const std::filesystem::path log =
        std::filesystem::temp_directory_path() / ("skyig_xvfb_" + std::to_string(::getpid()) + ".log");
    ::unsetenv("DISPLAY");
    x_ = std::make_unique<skyig::testing::VirtualX>("640x480x24", log.string());
    if (!x_->display().empty()) {
      ::setenv("DISPLAY", x_->display().c_str(), 1);
    } else {
      std::stringstream words;
      words << std::ifstream(log).rdbuf();
      std::cerr << "Xvfb did not start (deploy/setup.sh installs it); it said:\n" << words.str() << "\n";
    }
    std::filesystem::remove(log);
  }
  void TearDown() override { x_.reset(); }

 private:
  std::unique_ptr<skyig::testing::VirtualX> x_;
};

[[maybe_unused]] const ::testing::Environment* const kOwnXDisplay = ::testing::AddGlobalTestEnvironment(new OwnXDisplay);

}  // namespace
