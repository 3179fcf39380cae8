#pragma once
// Images as they leave the GPU: row 0 at the top, RGBA interleaved.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace skyig::render {

struct HdrImage {  // linear Rec.709, cd/m^2
  int width = 0;
  int height = 0;
  std::vector<float> rgba;
  const float* pixel(int column, int row) const {
    return &rgba[(static_cast<std::size_t>(row) * static_cast<std::size_t>(width) + static_cast<std::size_t>(column)) * 4];
  }
};

struct DisplayImage {  // frame-buffer values, 8 bits per channel
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
};

}  // namespace skyig::render
