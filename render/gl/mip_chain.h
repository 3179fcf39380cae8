#pragma once
// Mip levels by 2x2 box filtering on the CPU. llvmpipe's glGenerateMipmap takes ~150 ms for the
// moon's map, a visible stall on the first frame that shows a moon; this takes a few ms. No GL
// here: each level goes to the caller, which uploads it in its own format.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace skyig::render {

// The number of levels of a full chain down to 1x1.
inline int mipLevelCount(int width, int height) {
  int levels = 1;
  for (int s = std::max(width, height); s > 1; s /= 2) ++levels;
  return levels;
}

// Calls upload(level, width, height, texels) for level 0 (`base` itself) and every coarser level,
// each the mean of 2x2 texels of the one before (an odd edge repeats its last texel). Texel needs
// + and * by float (float, glm::vec3).
template <typename Texel, typename Upload>
void forEachMipLevel(std::vector<Texel> base, int width, int height, Upload&& upload) {
  const int levels = mipLevelCount(width, height);
  std::vector<Texel> level = std::move(base);
  int w = width, h = height;
  for (int l = 0; l < levels; ++l) {
    upload(l, w, h, level);
    if (l + 1 == levels) break;
    const int w2 = std::max(w / 2, 1), h2 = std::max(h / 2, 1);
    std::vector<Texel> next(static_cast<std::size_t>(w2) * static_cast<std::size_t>(h2));
    auto at = [&](int x, int y) -> const Texel& {
      return level[static_cast<std::size_t>(std::min(y, h - 1)) * static_cast<std::size_t>(w) +
                   static_cast<std::size_t>(std::min(x, w - 1))];
    };
    for (int y = 0; y < h2; ++y)
      for (int x = 0; x < w2; ++x)
        next[static_cast<std::size_t>(y) * static_cast<std::size_t>(w2) + static_cast<std::size_t>(x)] =
            0.25f * (at(2 * x, 2 * y) + at(2 * x + 1, 2 * y) + at(2 * x, 2 * y + 1) + at(2 * x + 1, 2 * y + 1));
    level = std::move(next);
    w = w2;
    h = h2;
  }
}

}  // namespace skyig::render
