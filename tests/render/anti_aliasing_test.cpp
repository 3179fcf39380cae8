// Analytic anti-aliasing of the edges the fragment stage computes (render/glsl/edge_coverage.glsl):
// the coverage formula against the area it names, and the horizon of rendered frames against
// the analytic horizon line, at the roll that makes a stepped horizon crawl in a dome.
#include "render/glsl/edge_coverage.h"

#include "physics/atmosphere/physical_camera.h"
#include "physics/physics.h"
#include "render/sky_renderer.h"
#include "tables/table_cache.h"
#include "tests/render/shared_renderer_test.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <random>

using namespace skyig;
using namespace skyig::render;
using namespace skyig::sky;
namespace atmosphere = skyig::atmosphere;

namespace {

// The area of the unit square (centred on the origin) where n . p < s, counted on a fine grid.
double countedShareBelow(double s, const glm::dvec2& n) {
  constexpr int kGrid = 1024;
  int below = 0;
  for (int j = 0; j < kGrid; ++j)
    for (int i = 0; i < kGrid; ++i) {
      const glm::dvec2 p((i + 0.5) / kGrid - 0.5, (j + 0.5) / kGrid - 0.5);
      below += glm::dot(n, p) < s ? 1 : 0;
    }
  return double(below) / (double(kGrid) * kGrid);
}

}  // namespace

// The share of a pixel a straight edge leaves on one side is the area it cuts off: a half at
// the centre, the linear ramp of an axis-aligned edge, a corner's triangle at 45 deg, and the
// counted area for any distance and direction (within the grid's 1/1024).
TEST(EdgeCoverage, APixelsShareIsTheAreaTheEdgeCutsOff) {
  EXPECT_DOUBLE_EQ(shader::squareShareBelow(0.0, glm::dvec2(0.6, 0.8)), 0.5);
  EXPECT_NEAR(shader::squareShareBelow(0.3, glm::dvec2(1.0, 0.0)), 0.8, 1e-12);
  EXPECT_NEAR(shader::squareShareBelow(-0.3, glm::dvec2(0.0, -1.0)), 0.2, 1e-12);
  const double diagonal = std::sqrt(0.5);
  // At 45 deg a line through the midpoints of two sides cuts off a triangle of 1/8.
  EXPECT_NEAR(shader::squareShareBelow(-0.5 * diagonal, glm::dvec2(diagonal, diagonal)), 0.125, 1e-12);
  EXPECT_DOUBLE_EQ(shader::squareShareBelow(diagonal + 1e-9, glm::dvec2(diagonal, diagonal)), 1.0);
  EXPECT_DOUBLE_EQ(shader::squareShareBelow(-diagonal - 1e-9, glm::dvec2(diagonal, -diagonal)), 0.0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi), distance(-0.8, 0.8);
  double worst = 0.0;
  for (int k = 0; k < 60; ++k) {
    const double a = angle(random), s = distance(random);
    const glm::dvec2 n(std::cos(a), std::sin(a));
    worst = std::max(worst, std::abs(shader::squareShareBelow(s, n) - countedShareBelow(s, n)));
  }
  EXPECT_LT(worst, 2e-3);
  // The value's gradient sets the distance: a value of 0.25 rising 0.5 a pixel is half a pixel in.
  EXPECT_NEAR(shader::pixelShareAbove(0.25, glm::dvec2(0.0, 0.5)), 1.0, 1e-12);
  EXPECT_NEAR(shader::pixelShareAbove(0.1, glm::dvec2(0.5, 0.0)), 0.7, 1e-12);
}

namespace {

std::shared_ptr<const atmosphere::AtmosphereModel> smallModel() {
  atmosphere::ModelConfig config;
  config.sizes = atmosphere::TableSizes::small();
  return std::make_shared<const atmosphere::AtmosphereModel>(
      atmosphere::loadOrPrecompute(config, std::filesystem::path(SKYIG_BINARY_DIR) / "atmosphere-test-cache"));
}

// The view ray through the channel's point (x, y) in pixels, (0, 0) the top left corner.
glm::dvec3 rayAt(const glm::dmat3& ndcToWorld, const ChannelConfig& c, double x, double y) {
  return glm::normalize(ndcToWorld * glm::dvec3(2.0 * x / c.width - 1.0, 1.0 - 2.0 * y / c.height, 1.0));
}

// How far the frame's horizon lies from where it should, in pixels, column by column, the line
// being where `sky(view)` crosses zero (positive above), found down the column's centre and its
// two sides. With `reference` (the channel supersampled and box filtered): the light the frame
// has more than the reference over the rows the line crosses and two either side, in rows of
// the step between the sky and the ground. Without: the edge where the sky's share of the rows
// the line crosses puts it against the line itself, each row's share read from its luminance
// between the sky's and the ground's, each extrapolated linearly from the two nearest whole rows
// of its side (for skies smooth on both sides; the physical sky's far ground changes too fast
// near the horizon for that). Columns whose two sides differ by less than a twentieth (a fifth
// without a reference) are left out: the share would be noise.
struct EdgeError {
  double mean = 0.0, worst = 0.0;
  int columns = 0;
};
EdgeError horizonEdgeError(const HdrImage& im, const HdrImage* reference, const SkyState& s, const ChannelConfig& c,
                           const std::function<double(const glm::dvec3&)>& sky) {
  const glm::dmat3 m = ndcToWorld(eyeToEnu(s.observer.attitude, c.offset), c.frustum);
  const auto luminanceOf = [](const HdrImage& image, int x, int y) {
    const float* p = image.pixel(x, y);
    return shader::rec709Luminance(glm::dvec3(p[0], p[1], p[2]));
  };
  const auto luminance = [&](int x, int y) { return luminanceOf(reference ? *reference : im, x, y); };
  // Where the line crosses the vertical at x (pixels), sky above it.
  const auto lineAt = [&](double x) {
    double top = 0.0, bottom = c.height;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (top + bottom);
      (sky(rayAt(m, c, x, mid)) > 0.0 ? top : bottom) = mid;
    }
    return 0.5 * (top + bottom);
  };
  EdgeError e;
  for (int x = 0; x < c.width; ++x) {
    if (sky(rayAt(m, c, x, 0.0)) <= 0.0 || sky(rayAt(m, c, x + 1.0, 0.0)) <= 0.0 ||
        sky(rayAt(m, c, x, c.height)) >= 0.0 || sky(rayAt(m, c, x + 1.0, c.height)) >= 0.0)
      continue;
    const double line = lineAt(x + 0.5);
    const double left = lineAt(x), right = lineAt(x + 1.0);
    // The rows the line crosses within this column.
    const int firstMixed = static_cast<int>(std::floor(std::min(left, right)));
    const int lastMixed = static_cast<int>(std::floor(std::max(left, right)));
    if (firstMixed < 2 || lastMixed > c.height - 3) continue;
    const double s1 = luminance(x, firstMixed - 1), s2 = luminance(x, firstMixed - 2);
    const double g1 = luminance(x, lastMixed + 1), g2 = luminance(x, lastMixed + 2);
    if (std::abs(s1 - g1) < (reference ? 0.05 : 0.2) * std::max(s1, g1)) continue;
    double error = 0.0;
    if (reference) {  // the light the frame has more than the reference near the edge, in rows of the step
      for (int y = firstMixed - 2; y <= lastMixed + 2; ++y) error += luminanceOf(im, x, y) - luminance(x, y);
      error = std::abs(error / (s1 - g1));
    } else {
      double skyRows = 0.0;
      for (int y = firstMixed; y <= lastMixed; ++y) {
        const double skyHere = s1 + (s1 - s2) * (firstMixed - 1 - y);
        const double groundHere = g1 + (g1 - g2) * (y - lastMixed - 1);
        skyRows += (luminance(x, y) - groundHere) / (skyHere - groundHere);
      }
      error = std::abs(firstMixed + skyRows - line);
    }
    e.mean += error;
    e.worst = std::max(e.worst, error);
    ++e.columns;
  }
  if (e.columns > 0) e.mean /= e.columns;
  return e;
}

class HorizonEdge : public skyig::render::testing::SharedRendererTest {
 protected:
  static void SetUpTestSuite() {
    SharedRendererTest::SetUpTestSuite();
    model_ = new std::shared_ptr<const atmosphere::AtmosphereModel>(smallModel());
  }
  static void TearDownTestSuite() {
    delete model_;
    model_ = nullptr;
    SharedRendererTest::TearDownTestSuite();
  }

  // A 320 x 200 channel (0.14 deg a pixel) rolled 25 deg, pitched so the horizon crosses it.
  static ChannelConfig channel(double pitchDeg, Frustum f = Frustum{22, 22, 14, 14}) {
    ChannelConfig c;
    c.width = 320;
    c.height = 200;
    c.frustum = f;
    c.offset.pitchDeg = pitchDeg;
    return c;
  }
  static SkyState state(const SkyConditions& conditions, double heightM, double rollDeg, double sunAlt) {
    ObserverState o;
    o.heightM = heightM;
    o.attitude = {200.0, 0.0, rollDeg};
    return buildSkyState(o, conditions, SunOverride{230.0, sunAlt});
  }
  static SkyConditions physical() {
    SkyConditions c;
    c.model = SkyModel::Physical;
    c.atmosphere = *model_;
    return c;
  }
  // Positive above the physical horizon, the cosine of its depression: mu > -rho / r.
  static std::function<double(const glm::dvec3&)> physicalHorizon(double heightM) {
    const double r = glm::length(atmosphere::physicalCamera(**model_, heightM));
    const double bottom = (*model_)->parameters(0).bottom_radius;
    const double rhoOverR = std::sqrt(r * r - bottom * bottom) / r;
    return [rhoOverR](const glm::dvec3& v) { return v.z + rhoOverR; };
  }
  static HdrImage render(const SkyState& s, const ChannelConfig& c) {
    renderer_->draw(s, c);
    while (s.conditions.atmosphere && renderer_->physicalPass()->current() != s.conditions.atmosphere.get())
      renderer_->draw(s, c);
    return renderer_->readHdr();
  }
  // An image kSuper times finer averaged over each pixel's kSuper^2 samples: the box filter's
  // image (to 1/kSuper of a pixel), the light varying within the pixel included.
  static constexpr int kSuper = 8;
  static HdrImage boxFiltered(const HdrImage& fine) {
    HdrImage out;
    out.width = fine.width / kSuper;
    out.height = fine.height / kSuper;
    out.rgba.assign(std::size_t(out.width) * out.height * 4, 0.0f);
    for (int y = 0; y < fine.height; ++y)
      for (int x = 0; x < fine.width; ++x)
        for (int k = 0; k < 4; ++k)
          out.rgba[(std::size_t(y / kSuper) * out.width + x / kSuper) * 4 + k] +=
              fine.pixel(x, y)[k] / float(kSuper * kSuper);
    return out;
  }
  static ChannelConfig finer(ChannelConfig c) {
    c.width *= kSuper;
    c.height *= kSuper;
    return c;
  }
  static HdrImage supersampled(const SkyState& s, const ChannelConfig& c) { return boxFiltered(render(s, finer(c))); }
  // The display frame as the light the screen gives (cd/m^2 per Rec.709 channel, eq. 17: ambient
  // plus peak times the decoded value), in an HdrImage so the edge is measured as the HDR one.
  static HdrImage shownLight(const DisplayImage& d, const DisplayParams& p) {
    HdrImage out;
    out.width = d.width;
    out.height = d.height;
    out.rgba.resize(d.rgba.size());
    for (std::size_t i = 0; i < d.rgba.size(); ++i)
      out.rgba[i] = static_cast<float>(p.ambientLuminance + p.maxLuminance * std::pow(d.rgba[i] / 255.0, p.gamma));
    return out;
  }
  static HdrImage shown(const SkyState& s, const ChannelConfig& c) {
    render(s, c);
    return shownLight(renderer_->readDisplay(), c.display);
  }
  static HdrImage shownSupersampled(const SkyState& s, const ChannelConfig& c) { return boxFiltered(shown(s, finer(c))); }
  // reference: against the supersampled frame, else against the luminance's own two sides.
  EdgeError measure(const SkyState& s, const ChannelConfig& c, const std::function<double(const glm::dvec3&)>& sky,
                    const char* what, bool reference) {
    const HdrImage ref = reference ? supersampled(s, c) : HdrImage{};
    const EdgeError e = horizonEdgeError(render(s, c), reference ? &ref : nullptr, s, c, sky);
    std::printf("%s: the horizon %.3f px from the analytic line (mean), %.3f at worst, over %d columns\n", what,
                e.mean, e.worst, e.columns);
    return e;
  }
  static inline std::shared_ptr<const atmosphere::AtmosphereModel>* model_ = nullptr;
};

}  // namespace

// At 25 deg of roll the physical sky's horizon lies where the box filter puts it: the frame's light
// near the edge within 0.06 of a pixel's step of the supersampled frame's on average and 0.2 at
// worst (drawn stepped: 0.20 and 0.44 low, 0.09 and 0.28 at 12 km, where the far ground is nearly
// the sky), for a forward channel low and at 12 km and a chin window looking down past it, by
// day and with the sun low (a bright horizon over a darker ground).
TEST_F(HorizonEdge, ThePhysicalHorizonAtRollLiesOnTheAnalyticLine) {
  const SkyConditions conditions = physical();
  struct Case {
    const char* what;
    double heightM, sunAlt, pitchDeg;
    Frustum frustum;
  };
  const Case cases[] = {
      {"forward, 581 m, sun 30 deg", 581.0, 30.0, 0.0, Frustum{22, 22, 14, 14}},
      {"forward, 581 m, sun 2 deg", 581.0, 2.0, 0.0, Frustum{22, 22, 14, 14}},
      {"forward, 12 km, sun 30 deg", 12000.0, 30.0, -3.5, Frustum{22, 22, 14, 14}},
      {"chin window, 581 m, sun 30 deg", 581.0, 30.0, -40.0, Frustum{22, 22, 5, 45}},
  };
  for (const Case& k : cases) {
    const SkyState s = state(conditions, k.heightM, 25.0, k.sunAlt);
    const ChannelConfig c = channel(k.pitchDeg, k.frustum);
    const EdgeError e = measure(s, c, physicalHorizon(k.heightM), k.what, true);
    EXPECT_GT(e.columns, 150) << k.what;
    EXPECT_LT(e.mean, 0.06) << k.what;
    EXPECT_LT(e.worst, 0.2) << k.what;
  }
}

// The analytic skies' horizon (the ground below view.z = 0, both sides smooth): the edge the
// mixed rows' luminance puts between their sides within 0.06 of a pixel of the line on average.
TEST_F(HorizonEdge, TheAnalyticHorizonAtRollLiesOnTheAnalyticLine) {
  const SkyState s = state(SkyConditions{}, 581.0, 25.0, 2.0);
  const EdgeError e = measure(s, channel(0.0), [](const glm::dvec3& v) { return v.z; }, "analytic sky, sun 2 deg", false);
  EXPECT_GT(e.columns, 150);
  EXPECT_LT(e.mean, 0.06);
  EXPECT_LT(e.worst, 0.2);
}

// What the display shows of the horizon at 25 deg of roll, against the channel drawn 8 times finer
// and averaged in the display's light (the box filter of what the screen shows). The pixels are
// mixed in the world's light and then mapped (the tone pass and the sky pass's folded tone map
// the same light, so both show the same frame), and a sky brighter than the ground takes a
// little more of the pixels they share than it covers: 0.078 and 0.089 of a pixel's step on
// average, 0.23 and 0.33 at worst, with the sun 30 and 2 deg up; drawn stepped, 0.18 and 0.19,
// 0.48 and 0.60 (the dither's +-1 code in all).
TEST_F(HorizonEdge, TheShownHorizonAtRollIsSmoothedNearlyAsTheShownLightsBoxFilter) {
  const SkyConditions conditions = physical();
  for (double sunAlt : {30.0, 2.0}) {
    SkyState s = state(conditions, 581.0, 25.0, sunAlt);
    const ChannelConfig c = channel(0.0);
    mapForDisplays(s, {c.display});
    const HdrImage reference = shownSupersampled(s, c);
    const EdgeError e = horizonEdgeError(shown(s, c), &reference, s, c, physicalHorizon(581.0));
    std::printf("shown, sun %.0f deg: the horizon %.3f px from the supersampled display's (mean), %.3f at worst, over %d "
                "columns\n", sunAlt, e.mean, e.worst, e.columns);
    EXPECT_GT(e.columns, 150);
    EXPECT_LT(e.mean, 0.12);
    EXPECT_LT(e.worst, 0.4);
  }
}
