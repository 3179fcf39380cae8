// The CPU mip chain of render/gl/mip_chain.h: a full chain to 1x1, each level the 2x2 mean of the
// one before, so the mean of a power-of-two image is kept at every level.
#include "render/gl/mip_chain.h"

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

using skyig::render::forEachMipLevel;
using skyig::render::mipLevelCount;

TEST(MipChain, LevelCountReachesOneTexel) {
  EXPECT_EQ(mipLevelCount(1, 1), 1);
  EXPECT_EQ(mipLevelCount(2048, 1024), 12);
  EXPECT_EQ(mipLevelCount(1024, 2048), 12);
  EXPECT_EQ(mipLevelCount(5, 3), 3);  // 5x3, 2x1, 1x1
}

TEST(MipChain, EachLevelKeepsThePowerOfTwoImagesMean) {
  const int w = 16, h = 8;
  std::vector<float> image(static_cast<std::size_t>(w * h));
  for (std::size_t i = 0; i < image.size(); ++i) image[i] = static_cast<float>((i * 37) % 11);
  const float mean = std::accumulate(image.begin(), image.end(), 0.0f) / static_cast<float>(image.size());
  std::vector<std::pair<int, int>> sizes;
  forEachMipLevel(image, w, h, [&](int level, int lw, int lh, const std::vector<float>& texels) {
    EXPECT_EQ(level, static_cast<int>(sizes.size()));
    ASSERT_EQ(texels.size(), static_cast<std::size_t>(lw * lh));
    sizes.emplace_back(lw, lh);
    EXPECT_NEAR(std::accumulate(texels.begin(), texels.end(), 0.0f) / static_cast<float>(texels.size()), mean, 1e-5f);
  });
  const std::vector<std::pair<int, int>> expected{{16, 8}, {8, 4}, {4, 2}, {2, 1}, {1, 1}};
  EXPECT_EQ(sizes, expected);
}

TEST(MipChain, AnOddEdgeRepeatsItsLastTexel) {
  // 3x1 -> 1x1: the mean of texels 0 and 1 (the third is dropped, as GL's box filter of a
  // non-power-of-two level does for its last column), not of all three.
  std::vector<float> last;
  forEachMipLevel(std::vector<float>{2.0f, 4.0f, 100.0f}, 3, 1,
                  [&](int, int, int, const std::vector<float>& texels) { last = texels; });
  ASSERT_EQ(last.size(), 1u);
  EXPECT_FLOAT_EQ(last[0], 3.0f);
}
