// The windowed path of `skyig serve`: a GLFW window with an OpenGL 4.5 core context renders
// the sky and presents exactly the tone-reproduced frame. Runs on an Xvfb of the
// test program's own (own_x_display.cpp).
#include "render/gl/glfw_window.h"
#include "render/sky_renderer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <vector>

using namespace skyig::render;
using namespace skyig::sky;

TEST(GlfwWindow, PresentsTheToneReproducedFrame) {
  ASSERT_TRUE(std::getenv("DISPLAY")) << "no X display: Xvfb did not start (tests/render/own_x_display.cpp)";
  WindowOptions options;
  options.width = 96;
  options.height = 64;
  options.vsync = false;
  GlfwWindowContext window(options);
  EXPECT_EQ(window.info().platform, "GLFW");
  EXPECT_FALSE(window.info().renderer.empty());

  ChannelConfig channel;
  channel.width = options.width;
  channel.height = options.height;
  const SkyState state = buildSkyState(ObserverState{}, SkyConditions{}, SunOverride{180.0, 30.0});
  SkyRenderer renderer;
  renderer.draw(state, channel);
  renderer.presentToDefaultFramebuffer(options.width, options.height);
  const DisplayImage frame = renderer.readDisplay();

  std::vector<unsigned char> back(static_cast<size_t>(options.width) * options.height * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, options.width, options.height, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  window.swapBuffers();
  // The back buffer is bottom-up, the frame top-down; compare RGB.
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(back[(static_cast<size_t>(options.height - 1 - y) * options.width + x) * 4 + k],
                  frame.rgba[(static_cast<size_t>(y) * options.width + x) * 4 + k])
            << x << "," << y;
  EXPECT_FALSE(window.closeRequested());
}
