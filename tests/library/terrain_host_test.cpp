// The example host (examples/terrain_host) rendered headless: skyig's sky behind a terrain the
// host drew with its own depth buffer, lit and fogged by skyig.
#include "examples/terrain_host/terrain_host.h"
#include "tests/library/library_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>

namespace skyig {
// GoogleTest's name for a parameter (ctest lists it beside the test's name).
inline void PrintTo(DepthConvention d, std::ostream* os) { *os << (d == DepthConvention::Standard ? "standard" : "reverse-Z"); }
}  // namespace skyig

namespace {

skyig::Sky afternoonSky() {
  skyig::Sky sky(skyig::testing::smallPhysicalSky());
  sky.update(skyig::testing::innsbruckAt(15, 0, 581.0), 0.0);  // 17:00 CEST; the view south, the sun to the west
  return sky;
}

double luminance(const std::vector<float>& rgb, std::size_t pixel) {
  return 0.2126729 * double(rgb[pixel * 3]) + 0.7151522 * double(rgb[pixel * 3 + 1]) +
         0.0721750 * double(rgb[pixel * 3 + 2]);
}

// The example host's afternoon frame, 160 x 100, in the host's depth convention `depth`.
terrain_host::Frame afternoonFrame(skyig::DepthConvention depth) {
  const skyig::Sky sky = afternoonSky();
  terrain_host::HeadlessContext context;
  terrain_host::Options o;
  o.width = 160;
  o.height = 100;
  o.depth = depth;
  return terrain_host::drawFrame(sky, o, terrain_host::HeadlessContext::procAddress());
}

class TerrainHost : public ::testing::TestWithParam<skyig::DepthConvention> {};

}  // namespace

// Where the terrain is, its pixels are exactly as the host drew them; where it left the far
// plane, the sky is there (a daylight sky: hundreds of cd/m^2), for both depth conventions.
TEST_P(TerrainHost, NoTerrainPixelIsOverwrittenByTheSky) {
  const terrain_host::Frame f = afternoonFrame(GetParam());
  std::size_t terrain = 0, skyPixels = 0, changed = 0, dark = 0;
  for (std::size_t i = 0; i < f.depth.size(); ++i) {
    if (f.depth[i] != static_cast<float>(f.farDepth)) {
      ++terrain;
      for (std::size_t c = 0; c < 3; ++c)
        if (f.final[i * 3 + c] != f.terrainOnly[i * 3 + c]) ++changed;
    } else {
      ++skyPixels;
      if (luminance(f.final, i) < 100.0) ++dark;
    }
  }
  EXPECT_GT(terrain, f.depth.size() / 4);
  EXPECT_GT(skyPixels, f.depth.size() / 4);
  EXPECT_EQ(changed, 0u);
  EXPECT_EQ(dark, 0u);
}

INSTANTIATE_TEST_SUITE_P(DepthConventions, TerrainHost,
                         ::testing::Values(skyig::DepthConvention::Standard, skyig::DepthConvention::ReverseZ),
                         [](const auto& test) {
                           return test.param == skyig::DepthConvention::Standard ? "StandardDepth" : "ReverseZ";
                         });

// Aerial perspective: the terrain fades into the haze of the sky's horizon. Up the image's
// middle column the terrain's luminance, a few hundred metres away nothing like the horizon's
// (72% off), comes within 15% of the sky just above the horizon at the last terrain row, beyond
// 50 km (12% at 123 km; Bruneton & Neyret 2008's in-scattering along the same paths as the sky's).
TEST(TerrainHostLook, DistantTerrainTendsToTheHorizonSky) {
  const terrain_host::Frame f = afternoonFrame(terrain_host::Options{}.depth);
  const std::size_t w = static_cast<std::size_t>(f.width), column = w / 2;
  std::size_t horizonRow = 0;  // the first sky row up the column (rows are bottom-up)
  while (horizonRow < static_cast<std::size_t>(f.height) && f.distanceM[horizonRow * w + column] > 0.0f) ++horizonRow;
  ASSERT_GT(horizonRow, 2u);
  ASSERT_LT(horizonRow, static_cast<std::size_t>(f.height));
  const double skyAtHorizon = luminance(f.final, horizonRow * w + column);
  auto offBy = [&](std::size_t row) { return std::abs(luminance(f.final, row * w + column) / skyAtHorizon - 1.0); };
  const std::size_t far = horizonRow - 1;
  std::printf("horizon sky %.1f cd/m^2; terrain at %.0f m off by %.1f%%, at %.0f m by %.1f%%, at %.0f m by %.1f%%\n",
              skyAtHorizon, double(f.distanceM[column]), 100 * offBy(0), double(f.distanceM[far / 2 * w + column]),
              100 * offBy(far / 2), double(f.distanceM[far * w + column]), 100 * offBy(far));
  EXPECT_GT(f.distanceM[far * w + column], 50000.0f);
  EXPECT_GT(offBy(0), 0.5);
  EXPECT_LT(offBy(far), 0.15);
  EXPECT_LT(offBy(far), offBy(far / 2));
  EXPECT_LT(offBy(far / 2), offBy(0));
}
