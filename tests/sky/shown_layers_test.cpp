// Which faint layers a state's displays can show (sky/shown_layers.h): here the point sources,
// against Schaefer's (1990) threshold of a point source on a background, taken at the darkest
// cell of the view sphere over kPointSourceMargin.
#include "sky/shown_layers.h"

#include "shaders/night/star_physics.h"

#include <gtest/gtest.h>

#include <vector>

using namespace skyig;
using namespace skyig::sky;

namespace {

std::vector<ViewCellLight> cellsDownTo(float darkestCdM2) {
  std::vector<ViewCellLight> cells(8);
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i].sunlit = darkestCdM2 * float(1 + i);
  cells[3].sunlit = 0.5f * darkestCdM2;  // the darkest is not the first
  cells[3].moonlit = 0.25f * darkestCdM2;
  cells[3].night = 0.25f * darkestCdM2;
  return cells;
}

}  // namespace

// By day (the darkest of the view 1e4 cd/m^2, a hazy bright sky): Venus at its brightest
// (V = -4.9) may be seen, so the displayed-star pass runs; Sirius (V = -1.46) cannot: its
// 9.6e-6 lux is under the cones' threshold on 1e3 cd/m^2 (the margin), 2.1e-5 lux.
TEST(PointSourcesSeen, VenusByDayButNotSirius) {
  const std::vector<ViewCellLight> day = cellsDownTo(1e4f);
  EXPECT_TRUE(pointSourcesSeen(day, shader::illuminanceOfMagnitude(-4.9)));
  EXPECT_FALSE(pointSourcesSeen(day, shader::illuminanceOfMagnitude(-1.46)));
  EXPECT_NEAR(shader::pointSourceThresholdLux(1e3), 2.10e-5, 0.01e-5);  // 4.808e-8 (1 + sqrt(0.3955e3))^2
}

// On a dark night (the darkest cell 2e-4 cd/m^2, 21.8 mag/arcsec^2) a sixth-magnitude star is
// seen; an eighth-magnitude one is not, even against a tenth of that sky.
TEST(PointSourcesSeen, SixthMagnitudeOnADarkNight) {
  const std::vector<ViewCellLight> night = cellsDownTo(2e-4f);
  EXPECT_TRUE(pointSourcesSeen(night, shader::illuminanceOfMagnitude(6.0)));
  EXPECT_FALSE(pointSourcesSeen(night, shader::illuminanceOfMagnitude(8.0)));
  // Without cells nothing is known: drawn.
  EXPECT_TRUE(pointSourcesSeen({}, 0.0));
  // No source at all: nothing to draw.
  EXPECT_FALSE(pointSourcesSeen(night, 0.0));
}
