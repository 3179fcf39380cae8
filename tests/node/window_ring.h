#pragma once
// N channels around the horizon, 72 degrees apart, each 36 degrees to either side and 10 down
// to 30 up: the outputs the window tests and the window benchmark present (a low sun gives
// each a gradient and a bright side, so a wrong channel or a shifted row shows).
#include "sky/channel.h"

#include <string>
#include <vector>

namespace skyig::services::testing {

inline std::vector<sky::ChannelConfig> windowRing(int n, int width, int height) {
  std::vector<sky::ChannelConfig> channels;
  for (int i = 0; i < n; ++i) {
    sky::ChannelConfig c;
    c.name = "c" + std::to_string(i);
    c.offset.yawDeg = 72.0 * i;
    c.frustum = {36.0, 36.0, 10.0, 30.0};
    c.width = width;
    c.height = height;
    channels.push_back(c);
  }
  return channels;
}

}  // namespace skyig::services::testing
