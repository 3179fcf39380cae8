#include "render/texture_readback.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace skyig::render {

// A float texture's pixels, top row first.
HdrImage readFloatTexture(GLuint texture, int width, int height) {
  HdrImage image{width, height, {}};
  const size_t row = static_cast<size_t>(image.width) * 4;
  std::vector<float> bottomUp(row * static_cast<size_t>(image.height));
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(bottomUp.size() * sizeof(float)),
                    bottomUp.data());
  image.rgba.resize(bottomUp.size());
  for (int y = 0; y < image.height; ++y)  // GL's rows start at the bottom, images' at the top
    std::copy_n(&bottomUp[static_cast<size_t>(image.height - 1 - y) * row], row, &image.rgba[static_cast<size_t>(y) * row]);
  return image;
}

// An 8-bit texture's pixels, top row first.
DisplayImage readDisplayTexture(GLuint texture, int width, int height) {
  DisplayImage image{width, height, {}};
  const size_t row = static_cast<size_t>(image.width) * 4;
  std::vector<std::uint8_t> bottomUp(row * static_cast<size_t>(image.height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(bottomUp.size()),
                    bottomUp.data());
  image.rgba.resize(bottomUp.size());
  for (int y = 0; y < image.height; ++y)
    std::copy_n(&bottomUp[static_cast<size_t>(image.height - 1 - y) * row], row, &image.rgba[static_cast<size_t>(y) * row]);
  return image;
}

}  // namespace skyig::render
