#pragma once
// The window tests' check that a window shows exactly a frame: the default framebuffer's back
// buffer, read before the swap, equals `frame` in RGB (the back buffer is bottom-up, the frame
// top-down).
#include "render/image.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace skyig::render::testing {

inline void expectBackBufferShows(const DisplayImage& frame) {
  std::vector<unsigned char> back(static_cast<std::size_t>(frame.width) * frame.height * 4);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, frame.width, frame.height, GL_RGBA, GL_UNSIGNED_BYTE, back.data());
  for (int y = 0; y < frame.height; ++y)
    for (int x = 0; x < frame.width; ++x)
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(back[(static_cast<std::size_t>(frame.height - 1 - y) * frame.width + x) * 4 + k],
                  frame.rgba[(static_cast<std::size_t>(y) * frame.width + x) * 4 + k])
            << x << "," << y;
}

}  // namespace skyig::render::testing
