// Which faint layers a state's displays can show (sky/shown_layers.h): the point sources,
// against Schaefer's (1990) threshold of a point source on a background, taken at the darkest
// cell of the view sphere over kPointSourceMargin; the sun's own sky after dusk, against the
// codes the scene's tone curve gives.
#include "sky/shown_layers.h"

#include "physics/stars/star_physics.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

namespace {

// A night sky of `nightCdM2` in every cell with the sun's twilight `sunlitCdM2` added in one, and
// the shown layers on the default display through the scene's own histogram-adjusted curve.
ShownLayers nightWithTwilight(float nightCdM2, float sunlitCdM2) {
  std::vector<ViewCellLight> cells(64);
  eye::LuminanceHistogram h;
  for (ViewCellLight& c : cells) c.night = nightCdM2;
  cells[7].sunlit = sunlitCdM2;
  for (const ViewCellLight& c : cells) h.add(double(c.sunlit) + double(c.night), 4.0 * 3.14159265358979 / 64.0);
  const DisplayParams display;
  const eye::ToneCurve curve = eye::histogramAdjustment(
      h, {std::max(display.ambientLuminance, 1e-3 * display.maxLuminance), display.ambientLuminance + display.maxLuminance,
          display.viewerAdaptationLuminance});
  return shownLayers(cells, {display}, {{display, curve}});
}

}  // namespace

// After dusk the sun's own sky is left out once even ten times its light moves no cell's code by
// a quarter: a ten-thousandth of the night sky's 2e-4 cd/m^2 is left out, a tenth (the
// twilight's arch near the end of astronomical twilight) is drawn. The moonlit sky and the
// night's own light follow the same rule: the night's light is drawn, there is no moon.
TEST(ShownLayers, TheSunsSkyIsLeftOutWhenItsTwilightIsTooFaintToMoveACode) {
  const ShownLayers faint = nightWithTwilight(2e-4f, 2e-8f);
  EXPECT_FALSE(faint.sunlitSky);
  EXPECT_TRUE(faint.nightLight);
  EXPECT_FALSE(faint.moonlitSky);
  EXPECT_TRUE(nightWithTwilight(2e-4f, 2e-5f).sunlitSky);
  // The threshold itself: the twilight at which ten times it first moves the code by 0.25.
  float lo = 2e-8f, hi = 2e-5f;
  for (int i = 0; i < 40; ++i) {
    const float mid = std::sqrt(lo * hi);
    (nightWithTwilight(2e-4f, mid).sunlitSky ? hi : lo) = mid;
  }
  std::printf("the sun's sky is first drawn at %.3g cd/m^2 in one cell of a 2e-4 cd/m^2 night\n", double(hi));
  EXPECT_GT(hi, 1e-7f);
  EXPECT_LT(hi, 2e-5f);
}
