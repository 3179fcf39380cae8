// Swap-barrier hardware (GLX_NV_swap_group) is optional: where the driver does not offer it the
// node says why and its windows swap on their own. Runs on an Xvfb of the test program's own
// (own_x_display.cpp), whose Mesa GLX offers no swap group.
#include "render/gl/glfw_window.h"
#include "render/gl/swap_group.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

using namespace skyig::render;

namespace {

// Sets DISPLAY (or unsets it) for one scope and puts it back.
class DisplayVariable {
 public:
  explicit DisplayVariable(const char* value) {
    if (const char* old = std::getenv("DISPLAY")) old_ = old;
    if (value) ::setenv("DISPLAY", value, 1);
    else ::unsetenv("DISPLAY");
  }
  ~DisplayVariable() {
    if (old_) ::setenv("DISPLAY", old_->c_str(), 1);
    else ::unsetenv("DISPLAY");
  }

 private:
  std::optional<std::string> old_;
};

}  // namespace

TEST(SwapGroup, HeadlessHasNoSwapGroupAndSaysWhy) {
  const DisplayVariable none(nullptr);
  const SwapGroupSupport s = querySwapGroupSupport();
  EXPECT_FALSE(s.available);
  EXPECT_NE(s.reason.find("no X display"), std::string::npos) << s.reason;
}

TEST(SwapGroup, UnreachableDisplayIsNamed) {
  const DisplayVariable nowhere(":9873");  // no X server listens there
  const SwapGroupSupport s = querySwapGroupSupport();
  EXPECT_FALSE(s.available);
  EXPECT_NE(s.reason.find("cannot open \":9873\""), std::string::npos) << s.reason;
}

// On the X display: the query and the join agree (Mesa under Xvfb: both say the extension is
// absent; an NVIDIA driver with GLX_NV_swap_group: the window joins group 1), and a window that
// could not join still swaps.
TEST(SwapGroup, WindowJoinsExactlyWhenTheDisplayOffersIt) {
  ASSERT_TRUE(std::getenv("DISPLAY")) << "no X display: Xvfb did not start (tests/render/own_x_display.cpp)";
  const SwapGroupSupport s = querySwapGroupSupport();
  WindowOptions options;
  options.width = 32;
  options.height = 24;
  options.vsync = false;
  GlfwWindowContext window(options);
  const std::string joined = joinSwapGroup(window.handle());
  if (s.available) {
    EXPECT_EQ(joined, "");
  } else {
    EXPECT_NE(s.reason.find("GLX_NV_swap_group absent"), std::string::npos) << s.reason;
    EXPECT_NE(joined.find("GLX_NV_swap_group absent"), std::string::npos) << joined;
  }
  window.swapBuffers();
  EXPECT_FALSE(window.closeRequested());
}
