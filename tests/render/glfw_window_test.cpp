// The windowed path of `skyig serve`: a GLFW window with an OpenGL 4.5 core context renders
// the sky and presents exactly the tone-reproduced frame. Runs on an Xvfb of the
// test program's own (own_x_display.cpp).
#include "render/gl/glfw_window.h"
#include "render/sky_renderer.h"
#include "tests/render/back_buffer.h"

#include <gtest/gtest.h>

#include <cstdlib>

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

  skyig::render::testing::expectBackBufferShows(frame);
  window.swapBuffers();
  EXPECT_FALSE(window.closeRequested());
}
