// The calibrated Milky Way map (physics/night/milky_way_map.h) and its placement in the sky.
#include "physics/night/diffuse_physics.h"
#include "physics/night/milky_way_map.h"
#include "physics/night/night_diffuse.h"
#include "sky/sky_state.h"
#include "physics/common/units.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>
#include <cstdio>
#include <numbers>

using namespace skyig;
using namespace skyig::sky;
using namespace skyig::sky::night;

namespace {

using skyig::kDeg;

glm::dvec3 radec(double raDeg, double decDeg) {
  return {std::cos(decDeg * kDeg) * std::cos(raDeg * kDeg), std::cos(decDeg * kDeg) * std::sin(raDeg * kDeg),
          std::sin(decDeg * kDeg)};
}

double y709(const glm::dvec3& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

// Mean luminance (S10) in a 2 deg cone, so one texel's noise does not decide.
double coneS10(const MilkyWayMap& map, const glm::dvec3& centre) {
  const glm::dvec3 a = glm::normalize(glm::cross(centre, glm::dvec3(0.0, 0.0, 1.0)));
  const glm::dvec3 b = glm::cross(centre, a);
  double sum = 0.0;
  int n = 0;
  for (double r : {0.0, 0.5, 1.0, 1.5, 2.0})
    for (int k = 0; k < 12; ++k, ++n) {
      const double phi = 2.0 * std::numbers::pi * k / 12.0;
      sum += y709(map.s10(glm::normalize(centre + std::tan(r * kDeg) * (std::cos(phi) * a + std::sin(phi) * b))));
    }
  return sum / n;
}

}  // namespace

TEST(MilkyWay, GalacticFrameMatchesKnownPoles) {
  EXPECT_NEAR(shader::galacticLatitude(radec(192.85948, 27.12825)) / kDeg, 90.0, 0.01);
  EXPECT_NEAR(shader::galacticLatitude(radec(266.40499, -28.93617)) / kDeg, 0.0, 0.01);  // l = b = 0
  const glm::dvec2 uv = shader::milkyWayTexCoord(radec(123.0, -40.0));
  const glm::dvec3 back = shader::milkyWayDirection(uv);
  EXPECT_NEAR(glm::length(back - radec(123.0, -40.0)), 0.0, 1e-12);
  // The README's pixel convention: column x has RA = 90 - 360 (x + 0.5) / 2048 deg.
  EXPECT_NEAR(shader::milkyWayTexCoord(radec(90.0 - 360.0 * 100.5 / 2048.0, 0.0)).x * 2048.0, 100.5, 1e-6);
}

// Calibration: the anchors hold after the clip of the photograph's background.
TEST(MilkyWay, CalibratedToPublishedStarlight) {
  const auto map = MilkyWayMap::standard();
  EXPECT_NEAR(map->meanPoleS10(), kPoleS10, 0.15 * kPoleS10);
  EXPECT_NEAR(map->brightS10(), kBrightestS10, 0.05 * kBrightestS10);
}

// The band passes through the galactic plane's known directions, not the galactic poles.
TEST(MilkyWay, BandThroughSagittariusAndCygnusNotThePoles) {
  const auto map = MilkyWayMap::standard();
  const double northPole = coneS10(*map, radec(192.85948, 27.12825));
  const double southPole = coneS10(*map, radec(12.85948, -27.12825));
  const double sagittarius = coneS10(*map, radec(270.0, -24.0));  // the Large Sagittarius Star Cloud
  const double cygnus = coneS10(*map, radec(300.0, 36.0));         // the Cygnus Star Cloud
  const double scutum = coneS10(*map, radec(281.0, -7.0));
  for (double onBand : {sagittarius, cygnus, scutum}) {
    EXPECT_GT(onBand, 4.0 * northPole);
    EXPECT_GT(onBand, 4.0 * southPole);
  }
  EXPECT_LT(northPole, 40.0);
  EXPECT_LT(southPole, 40.0);
}

// The catalogue's stars are drawn separately: the map must not show them again. Vega (V = 0.03)
// and Sirius (V = -1.46) are not brighter than the ring of sky around them.
TEST(MilkyWay, BrightStarsRemoved) {
  const auto map = MilkyWayMap::standard();
  for (const glm::dvec3& star : {radec(279.2347, 38.7837), radec(101.2872, -16.7161), radec(88.7929, 7.4071)}) {
    const double at = y709(map->s10(star));
    const glm::dvec3 a = glm::normalize(glm::cross(star, glm::dvec3(0.0, 0.0, 1.0)));
    const glm::dvec3 b = glm::cross(star, a);
    double ring = 0.0;
    for (int k = 0; k < 16; ++k) {
      const double phi = 2.0 * std::numbers::pi * k / 16.0;
      ring += y709(map->s10(glm::normalize(star + std::tan(1.5 * kDeg) * (std::cos(phi) * a + std::sin(phi) * b)))) / 16.0;
    }
    EXPECT_LT(at, 1.5 * ring + 2.0) << "star at " << star.x << ", " << star.y << ", " << star.z;
  }
}

// Placement: the renderer's view-to-J2000 frame is the transpose of the stars' J2000-to-ENU
// matrix, so the galactic centre lands where the ephemeris puts it.
TEST(MilkyWay, PlacedWithTheStarsMatrix) {
  ObserverState o;
  o.latitudeDeg = -30.0;  // Sagittarius high in a southern winter night
  o.longitudeDeg = 21.0;
  o.utc = {2026, 7, 15, 21.0 * 3600.0};
  const SkyState s = buildSkyState(o, SkyConditions{});
  const auto sky = nightDiffuseSky(s);
  ASSERT_TRUE(sky.has_value());
  const glm::dvec3 gc = radec(266.40499, -28.93617);
  const ephemeris::Vec3 enu = ephemeris::j2000DirectionToEnu({gc.x, gc.y, gc.z}, *s.ephemeris);
  const glm::dvec3 view(enu.x, enu.y, enu.z);
  ASSERT_GT(view.z, 0.5);
  const glm::dvec3 expected = nightExtinction(*sky, view) * shader::kS10CdM2 * sky->milkyWay->s10(gc);
  const glm::dvec3 got = nightDiffuseRadiance(*sky, view).milkyWay;
  EXPECT_NEAR(y709(got), y709(expected), 0.05 * y709(expected));  // aberration: 20", a fraction of a texel
  EXPECT_GT(y709(got), 100.0 * shader::kS10CdM2);
}

// The map is smooth at its own texel scale, as the sky is. The shipped panorama was JPEG
// compressed once: its 8 x 8 blocks (1.4 deg) show as a grid of steps, the first differences
// across the block edges (between columns or rows 8k - 1 and 8k) 1.3-1.4 times those inside the
// blocks. And a grey opening alone leaves a mosaic, each local maximum of its erosion dilated into
// a flat 5 x 5 plateau with a step to the next, where a map made of plateaus and steps has a
// second difference as large as its first (each step of height h gives |d1| = h and |d2| = 2h:
// the ratio is 2; white noise gives 1.7), a map smooth over w texels a ratio of about 2 / w.
// Measured over the band (|b| <= 20 deg, |Dec| <= 60 deg); without the smoothing: grid steps
// 1.12 (rows) and 1.10 (columns) times the inside ones, second over first difference 1.38.
TEST(MilkyWay, NoTexelSizedSteps) {
  const auto map = MilkyWayMap::standard();
  const int w = map->width(), h = map->height();
  const auto& t = map->texels();
  auto at = [&](int x, int y) {
    return y709(glm::dvec3(t[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>((x + w) % w)]));
  };
  double slope = 0.0, curvature = 0.0;
  double edge[2] = {0.0, 0.0}, inside[2] = {0.0, 0.0};  // [0]: along rows, [1]: along columns
  int edges[2] = {0, 0}, insides[2] = {0, 0};
  for (int y = h / 6; y < h - h / 6; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::dvec3 dir = shader::milkyWayDirection(glm::dvec2((x + 0.5) / w, (y + 0.5) / h));
      if (std::abs(shader::galacticSinLatitude(dir)) > std::sin(20.0 * kDeg)) continue;
      slope += std::abs(at(x + 1, y) - at(x, y));
      curvature += std::abs(at(x + 1, y) - 2.0 * at(x, y) + at(x - 1, y));
      const double across[2] = {std::abs(at(x + 1, y) - at(x, y)), std::abs(at(x, y + 1) - at(x, y))};
      const int phase[2] = {x % 8, y % 8};
      for (int k = 0; k < 2; ++k) {
        if (phase[k] == 7) {
          edge[k] += across[k];
          ++edges[k];
        } else {
          inside[k] += across[k];
          ++insides[k];
        }
      }
    }
  }
  ASSERT_GT(slope, 0.0);
  std::printf("second over first difference along the rows of the band: %.3f\n", curvature / slope);
  EXPECT_LT(curvature / slope, 0.8) << "second over first difference along the rows of the band";
  for (int k = 0; k < 2; ++k) {
    const double ratio = (edge[k] / edges[k]) / (inside[k] / insides[k]);
    std::printf("%s: step across the 8-texel grid / inside it = %.3f\n", k == 0 ? "rows" : "columns", ratio);
    EXPECT_LT(ratio, 1.05) << (k == 0 ? "along the rows" : "along the columns");
  }
}

// The map's colour follows its light: where the photograph is at its black, the calibration's
// floor is grey (the faint starlight there has no colour the photograph can tell), and what
// rises above it carries the photograph's colour, so the chromaticity changes smoothly from the
// floor into the band. (Scaling a barely-lit texel's own colour up to the floor's luminance
// gave texels of pure blue, R = G = 0, where only the photograph's blue channel had left its
// black: a hard-edged, scalloped blue patch along the band on a dark site's display.)
TEST(MilkyWay, TheColourFollowsTheLightWithoutSteps) {
  const auto map = MilkyWayMap::standard();
  const int w = map->width(), h = map->height();
  const auto& t = map->texels();
  auto chroma = [&](int x, int y) {
    const glm::dvec3 c(t[static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>((x + w) % w)]);
    const double sum = c.r + c.g + c.b;
    return sum > 0.0 ? glm::dvec2(c.r / sum, c.b / sum) : glm::dvec2(1.0 / 3.0);
  };
  std::vector<double> steps;
  double leastShare = 1.0;
  for (int y = 1; y < h - 1; ++y)
    for (int x = 0; x < w; ++x) {
      const glm::dvec2 c = chroma(x, y);
      leastShare = std::min({leastShare, c.x, c.y, 1.0 - c.x - c.y});
      steps.push_back(std::max(glm::length(chroma(x + 1, y) - c), glm::length(chroma(x, y + 1) - c)));
    }
  std::sort(steps.begin(), steps.end());
  const double p999 = steps[static_cast<std::size_t>(0.999 * static_cast<double>(steps.size()))], largest = steps.back();
  std::printf("chromaticity step between neighbouring texels: 99.9th percentile %.4f, largest %.4f; least channel share %.3f\n",
              p999, largest, leastShare);
  // Measured: 0.092, 0.0187 and 0.046 (0.000, 0.745 and 1 when each texel's own colour was
  // scaled up); the reddest texels are the photograph's emission nebulae.
  EXPECT_GT(leastShare, 0.05);  // no texel of one or two channels
  EXPECT_LT(p999, 0.03);
  EXPECT_LT(largest, 0.08);
}
