// A projector channel in a window (`skyig serve`'s windows): the window shows exactly what the
// projector is sent, the warped and blended image at the projector's resolution, not the
// channel's own frame. On an Xvfb of the test program's own (own_x_display.cpp).
#include "render/gl/glfw_window.h"
#include "render/sky_renderer.h"
#include "tests/render/back_buffer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

using namespace skyig::render;
using namespace skyig::sky;
using skyig::calibration::FloatMap;
using skyig::calibration::ProjectorCalibration;

TEST(GlfwWindow, PresentsTheProjectorImage) {
  ASSERT_TRUE(std::getenv("DISPLAY")) << "no X display: Xvfb did not start (tests/render/own_x_display.cpp)";
  WindowOptions options;
  options.width = 120;
  options.height = 80;
  options.vsync = false;
  GlfwWindowContext window(options);

  ChannelConfig channel;
  channel.width = 90;
  channel.height = 60;
  auto projector = std::make_shared<ProjectorCalibration>();
  projector->width = options.width;
  projector->height = options.height;
  projector->camera = {Attitude{0.0, 10.0, 0.0}, Frustum{30, 30, 20, 20}};
  projector->cameraGiven = true;
  // A 2x2 warp showing the channel's middle, turned upside down, and a blend ramp to the right.
  projector->warp = FloatMap{2, 2, 2, {0.2f, 0.9f, 0.8f, 0.9f, 0.2f, 0.1f, 0.8f, 0.1f}};
  projector->alpha = FloatMap{2, 1, 1, {1.0f, 0.3f}};
  const SkyState state = buildSkyState(ObserverState{}, SkyConditions{}, SunOverride{180.0, 30.0});
  SkyRenderer renderer;
  renderer.drawProjector(state, channel, projector);
  renderer.presentToDefaultFramebuffer(options.width, options.height);
  const DisplayImage frame = renderer.readProjectorDisplay();
  ASSERT_EQ(frame.width, options.width);
  skyig::render::testing::expectBackBufferShows(frame);
  window.swapBuffers();
  // The blend shows: the right edge sends less than the left.
  EXPECT_LT(frame.rgba[(40u * options.width + options.width - 1) * 4 + 2], frame.rgba[(40u * options.width) * 4 + 2]);
}
